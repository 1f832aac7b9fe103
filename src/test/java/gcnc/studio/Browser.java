package gcnc.studio;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.stream.Stream;
import org.openqa.selenium.Dimension;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * Debian's Chromium, headless, driven through its own chromedriver (no download: Selenium is told
 * both files). The studio's browser tests need them: when they are missing the tests fail and say
 * how to get them, rather than skip and let a CI run pass without ever opening the page.
 */
final class Browser {
    /** How often a wait asks the page again: Selenium's default (500 ms) added half a second to most steps. */
    static final Duration POLL = Duration.ofMillis(40);
    private static WebDriver shared;
    /** The window's size as --window-size made it: each class gets it back (the screenshots are this size). */
    private static Dimension window;

    private Browser() {
    }

    /**
     * The one Chromium of this test JVM, started by the first browser test class that asks and quit when
     * the JVM exits: each class used to start (and quit) its own, a few seconds each on a busy machine.
     * Each class gets it on a blank page with no dialog open and the window at its start size.
     */
    static synchronized WebDriver shared() {
        if (shared == null) {
            WebDriver d = start();
            Runtime.getRuntime().addShutdownHook(new Thread(d::quit, "gcnc-test-chromium-quit"));
            shared = d;
            window = d.manage().window().getSize();
        }
        blank(shared);
        if (!shared.manage().window().getSize().equals(window)) {
            shared.manage().window().setSize(window); // SetupPicturesTest sizes it to its pictures
        }
        return shared;
    }

    /**
     * Leaves the page for a blank one, the "leave with unsaved changes?" question answered yes: a class
     * done with the browser calls it (a studio page left open would go on asking its closed server).
     */
    static void blank(WebDriver d) {
        for (int i = 0; i < 3 && !"about:blank".equals(currentUrl(d)); i++) {
            acceptAnyAlert(d);
            try {
                d.get("about:blank");
            } catch (org.openqa.selenium.UnhandledAlertException e) {
                // the page asked before leaving (and the driver may have said no): asked again
            }
            acceptAnyAlert(d);
        }
    }

    /**
     * A browser class's end: the JVM's one Chromium left on a blank page for the next class (the
     * JVM's exit quits it), and the class's studio closed.
     */
    static void release(WebDriver d, Studio studio) {
        if (d != null) {
            blank(d);
        }
        if (studio != null) {
            studio.close();
        }
    }

    private static String currentUrl(WebDriver d) {
        try {
            return d.getCurrentUrl();
        } catch (org.openqa.selenium.UnhandledAlertException e) {
            return null;
        }
    }

    private static void acceptAnyAlert(WebDriver d) {
        try {
            d.switchTo().alert().accept();
        } catch (org.openqa.selenium.NoAlertPresentException e) {
            // none open
        }
    }

    /** A wait of at most {@code timeout} that looks again every {@link #POLL}. */
    static WebDriverWait waitUpTo(WebDriver d, Duration timeout) {
        return new WebDriverWait(d, timeout, POLL);
    }

    static WebDriver start() {
        Path chromium = find("chromium", "chromium-browser").orElse(null);
        Path driver = find("chromedriver").orElse(null);
        if (chromium == null || driver == null) {
            fail("the studio's browser tests need Chromium and its driver (" + (chromium == null ? "no chromium" : "")
                    + (chromium == null && driver == null ? ", " : "") + (driver == null ? "no chromedriver" : "")
                    + " on the PATH): run `bash setup.sh` (it installs the Debian packages chromium and chromium-driver)");
        }
        ChromeDriverService service = new ChromeDriverService.Builder().usingDriverExecutable(driver.toFile())
                .usingAnyFreePort().withLogOutput(java.io.OutputStream.nullOutputStream()).build();
        ChromeOptions options = new ChromeOptions();
        options.setBinary(chromium.toFile());
        options.addArguments("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1500,1000",
                "--lang=en-US", "--no-first-run", "--disable-extensions");
        ChromeDriver d = new ChromeDriver(service, options);
        d.manage().timeouts().scriptTimeout(Duration.ofSeconds(20));
        return d;
    }

    /** The first of the names found on the PATH, as a file that can be run. */
    static Optional<Path> find(String... names) {
        String path = System.getenv().getOrDefault("PATH", "/usr/bin:/bin");
        for (String name : names) {
            Optional<Path> p = Stream.of(path.split(File.pathSeparator)).map(d -> Path.of(d, name))
                    .filter(Files::isExecutable).findFirst();
            if (p.isPresent()) {
                return p;
            }
        }
        return Optional.empty();
    }

    /**
     * A PNG of the page, under docs/studio/ (the screens docs/studio.md shows): taken on every run (a
     * screen that cannot be drawn fails the test), written when there is none yet or when the run
     * is asked to ({@code gradle junitPlatformTest -PupdateScreenshots}, as -PupdateGolden for the
     * goldens), so that a test run does not leave the checkout changed by a blinking cursor.
     */
    static void screenshot(WebDriver d, String name) throws java.io.IOException {
        byte[] png = ((TakesScreenshot) d).getScreenshotAs(OutputType.BYTES);
        Path file = Path.of("docs/studio", name + ".png");
        if (!Files.exists(file) || Boolean.getBoolean("gcnc.updateScreenshots")) {
            Files.createDirectories(file.getParent());
            Files.write(file, png);
        }
    }
}
