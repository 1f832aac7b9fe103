package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.openqa.selenium.Dimension;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;

/**
 * The README's pictures of a drawing and a setup sheet (issue 22), made from the reviewed golden
 * files of gcnc.cli.ProgramTermsGoldenTest by the browser the studio's tests drive ({@link Browser}:
 * no new dependency to turn an SVG into a PNG). Taken on every run, so a page that cannot be drawn
 * fails; written to docs/images/ only when missing or with {@code -PupdateScreenshots}.
 */
class SetupPicturesTest {
    private static final Path GOLDEN = Path.of("src/test/resources/golden/terms");

    @Test
    void theDrawingAndTheSetupSheetOfTheInchPin() throws Exception {
        WebDriver browser = Browser.shared();
        try {
            picture(browser, GOLDEN.resolve("pin-inch.haas.svg"), 1000, "pin-drawing");
            picture(browser, GOLDEN.resolve("pin-inch.haas.html"), 1100, "pin-setup-sheet");
        } finally {
            Browser.blank(browser); // the JVM's one Chromium (Browser.shared gives the next class its window size back)
        }
    }

    private static void picture(WebDriver browser, Path page, int width, String name) throws Exception {
        browser.manage().window().setSize(new Dimension(width, 900));
        browser.get(page.toAbsolutePath().toUri().toString());
        JavascriptExecutor js = (JavascriptExecutor) browser;
        // no scroll bars, and a window whose inside (not its outside) is the page's size
        js.executeScript("document.documentElement.style.overflow = 'hidden';");
        long height = (Long) js.executeScript("return Math.ceil(document.documentElement.getBoundingClientRect().height);");
        long frameX = (Long) js.executeScript("return window.outerWidth - window.innerWidth;");
        long frameY = (Long) js.executeScript("return window.outerHeight - window.innerHeight;");
        browser.manage().window().setSize(new Dimension((int) (width + frameX), (int) (Math.max(200, height) + frameY)));
        byte[] png = ((TakesScreenshot) browser).getScreenshotAs(OutputType.BYTES);
        assertTrue(png.length > 10_000, name + ": an empty picture");
        Path file = Path.of("docs/images", name + ".png");
        if (!Files.exists(file) || Boolean.getBoolean("gcnc.updateScreenshots")) {
            Files.createDirectories(file.getParent());
            Files.write(file, png);
        }
    }
}
