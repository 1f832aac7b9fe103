package gcnc.studio;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.stream.Stream;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;

/**
 * Debian's Chromium, headless, driven through its own chromedriver (no download: Selenium is told
 * both files). The studio's browser tests need them: when they are missing the tests fail and say
 * how to get them, rather than skip and let a CI run pass without ever opening the page.
 */
final class Browser {
    private Browser() {
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
