package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.cli.WearOffsetsTest;
import gcnc.tables.ErrorMessages;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openqa.selenium.By;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.support.ui.ExpectedConditions;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * The test cut in headless Chromium (docs/studio.md, "Test cut"): a metric Fanuc part run to its end on the
 * studio's virtual controller, the form for its tool offset opens by itself; a typo (37.5 for 39.975) is
 * refused with E872 and nothing is written; the real measurement is saved to the offsets file, and the
 * next Arm's pre-flight names the wear. Each wait is on the condition (the form's data-state), never a sleep.
 */
class StudioTestCutBrowserTest {
    static WebDriver browser;
    static Studio studio;
    static Path dir;
    static Path offsets;

    @BeforeAll
    static void start() throws Exception {
        browser = Browser.shared();
        dir = Files.createDirectory(Files.createTempDirectory("gcnc-studio-testcut").resolve("programs"));
        offsets = dir.resolve("shop.offsets");
        Files.writeString(offsets, "# the shop's wear\n");
        Files.writeString(dir.resolve("part.nc"), WearOffsetsTest.METRIC);
        Session s = Session.open(Session.Options.defaults().withMachine("fanuc").withOffsets(offsets));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test", new Studio.Running(5, null)));
    }

    @AfterAll
    static void stop() {
        Browser.release(browser, studio);
    }

    /** Waits for {@code id}'s data-state; a timeout says what the page showed. */
    private static void waitState(WebDriverWait wait, String id, String state) {
        try {
            wait.until(ExpectedConditions.attributeToBe(By.id(id), "data-state", state));
        } catch (org.openqa.selenium.TimeoutException e) {
            throw new AssertionError("no " + state + " on #" + id + ": status '" + browser.findElement(By.id("status")).getText()
                    + "'\n" + browser.findElement(By.id("run")).getText(), e);
        }
    }

    private static void type(String id, String text) {
        WebElement e = browser.findElement(By.id(id));
        e.clear();
        e.sendKeys(text);
    }

    @Test
    void afterARunTheFormRefusesATypoSavesTheWearAndTheNextArmUsesIt() throws Exception {
        WebDriverWait wait = Browser.waitUpTo(browser, Duration.ofSeconds(60)); // a shared, busy machine
        browser.get(studio.url("part.nc").toString());
        wait.until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-ready", "true"));
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("counts"), "no errors"));
        browser.findElement(By.id("run-open")).click();
        wait.until(ExpectedConditions.visibilityOfElementLocated(By.id("run")));
        browser.findElement(By.id("run-arm")).click();
        waitState(wait, "run-state", "armed");
        assertTrue(!browser.findElement(By.id("runarmed")).getText().contains("wear in force"), "no wear yet");
        browser.findElement(By.id("run-start")).click();
        waitState(wait, "run-state", "finished");
        // the form opens by itself at the end of the run: one per tool offset the program uses
        waitState(wait, "testcut", "ready");
        String form = browser.findElement(By.id("testcut")).getText();
        assertTrue(form.contains("in mm as the program writes them (X a diameter)"), form);
        assertTrue(form.contains("saved to shop.offsets"), form);
        assertTrue(form.contains("T01: wear T01 X0.000 Z0.000 (diameter, mm)"), form);
        assertEquals(1, browser.findElements(By.cssSelector("#testcut form.wearform")).size());
        // 37.5 typed where 39.975 was measured: a step of 2.5 mm, refused, nothing written
        type("wear-1-mx", "37.5");
        type("wear-1-px", "40.");
        browser.findElement(By.id("wear-1-save")).click();
        waitState(wait, "wear-1", "refused");
        String refused = browser.findElement(By.id("wear-1-result")).getText();
        assertTrue(refused.contains("Refused, nothing saved: shop.offsets:1: E872:"), refused);
        assertTrue(refused.contains("more than wear.max_step = 0.5 mm"), refused);
        assertEquals("# the shop's wear\n", Files.readString(offsets));
        // the real measurement: 39.96 where the program cuts 40.
        type("wear-1-mx", "39.96");
        browser.findElement(By.id("wear-1-save")).click();
        waitState(wait, "wear-1", "saved");
        String saved = browser.findElement(By.id("wear-1-result")).getText();
        assertTrue(saved.contains("X wear 0.000 → +0.040 (+0.040 mm = programmed X40. − measured X39.96)"), saved);
        assertTrue(saved.contains("saved T01 X+0.040 Z0.000 (diameter, mm) to shop.offsets; the program re-verified with it:"
                + " no errors"), saved);
        assertEquals("# the shop's wear\nwear.1 = 0.04, 0\n", Files.readString(offsets));
        // the next arm's pre-flight says which wear the DMC was compiled with
        browser.findElement(By.id("run-arm")).click();
        waitState(wait, "run-state", "armed");
        String armed = browser.findElement(By.id("runarmed")).getText();
        assertTrue(armed.contains("wear in force (" + offsets + "): T01 X+0.040 Z0.000 (diameter, mm)"), armed);
        Browser.screenshot(browser, "testcut");
    }
}
