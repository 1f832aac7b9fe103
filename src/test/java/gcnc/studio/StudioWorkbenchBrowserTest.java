package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.openqa.selenium.By;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.Keys;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.interactions.Actions;
import org.openqa.selenium.support.ui.ExpectedConditions;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * The studio's workbench in headless Chromium, on a copy of the bishop (machine thesis-2004): the hover
 * on a word, the scrub through the blocks, Configure's impact before saving and the save, a click on a
 * DMC line, and a click on the path of a subprogram's block. Each screen is saved under docs/studio/.
 */
class StudioWorkbenchBrowserTest {
    static WebDriver browser;
    static Studio studio;
    static Path dir;
    WebDriverWait wait;

    @BeforeAll
    static void start() throws Exception {
        browser = Browser.shared();
        dir = Files.createDirectory(Files.createTempDirectory("gcnc-studio-workbench").resolve("programs"));
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test"));
    }

    @AfterAll
    static void stop() {
        Browser.release(browser, studio);
    }

    @BeforeEach
    void aFreshBishop() throws Exception {
        Files.deleteIfExists(dir.resolve("bishop.nc"));
        Files.copy(Path.of("samples/bishop.nc"), dir.resolve("bishop.nc"));
        wait = Browser.waitUpTo(browser, Duration.ofSeconds(45)); // a shared, busy machine
    }

    /** The class's studio on the bishop, checked, simulated and compiled (the tests with a studio of their own skip it). */
    private void openTheBishop() throws Exception {
        open(studio, "bishop.nc");
        int lines = StudioBrowserTest.bishopDmcLines(); // what a compile of the same program writes, line for line
        wait.until(d -> d.findElements(By.cssSelector("#dmc li")).size() == lines);
    }

    private void open(Studio on, String name) {
        browser.get("about:blank");
        try {
            browser.switchTo().alert().accept();
        } catch (org.openqa.selenium.NoAlertPresentException e) {
            // none
        }
        browser.get(on.url(name).toString());
        wait.until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-ready", "true"));
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("counts"), "no errors"));
    }

    private Object js(String script, Object... args) {
        return ((JavascriptExecutor) browser).executeScript(script, args);
    }

    private int cursorLine() {
        return Integer.parseInt(browser.findElement(By.id("cursor")).getAttribute("data-line"));
    }

    /** The mouse over the middle of the first {@code word} on editor line {@code line}, as a user points at it. */
    private void pointAt(int line, String word) {
        @SuppressWarnings("unchecked")
        List<Number> xy = (List<Number>) js("""
                const line = document.querySelectorAll('.cm-content .cm-line')[arguments[0] - 1];
                const walker = document.createTreeWalker(line, NodeFilter.SHOW_TEXT);
                let text = '', nodes = [];
                for (let n = walker.nextNode(); n; n = walker.nextNode()) { nodes.push([n, text.length]); text += n.data; }
                const at = text.indexOf(arguments[1]) + 1;
                for (const [n, start] of nodes) {
                  if (at >= start && at < start + n.data.length) {
                    const r = document.createRange(); r.setStart(n, at - start); r.setEnd(n, at - start + 1);
                    const b = r.getBoundingClientRect(); return [b.left + b.width / 2, b.top + b.height / 2];
                  }
                }
                return null;""", line, word);
        new Actions(browser).moveToLocation(0, 0).perform();
        new Actions(browser).moveToLocation((int) Math.round(xy.get(0).doubleValue()),
                (int) Math.round(xy.get(1).doubleValue())).perform();
    }

    @Test
    void hoverOnAWordShowsItsFunctionAndTheModalStateAfterTheBlock() throws Exception {
        openTheBishop();
        pointAt(6, "G01"); // N135 G01 Z-04500
        WebElement tip = wait.until(ExpectedConditions.visibilityOfElementLocated(By.cssSelector(".cm-tooltip-hover .gc-hover")));
        String text = tip.getText();
        assertTrue(text.contains("G01 — Linear interpolation"), text); // thesis-2004's g_codes.csv, English column
        assertTrue(text.contains("After this block:"), text);
        assertTrue(text.contains("Units: G21 mm"), text);
        assertTrue(text.contains("F150"), text); // from G50 S5000 M11 M03 F150 on line 4
        assertTrue(text.contains("Work offset: G54"), text);
        assertTrue(text.contains("Tool: T1"), text);
        assertTrue(text.contains("Tool at: X2034 Z-4500"), text);
        Browser.screenshot(browser, "hover");
        pointAt(4, "M03");
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.cssSelector(".cm-tooltip-hover .gc-hover .function"), "M03"));
        assertTrue(browser.findElement(By.cssSelector(".cm-tooltip-hover .gc-hover")).getText().contains("Spindle: G97 (limit 5000)"), // G50 S5000 clamps; no S rpm given yet
                browser.findElement(By.cssSelector(".cm-tooltip-hover .gc-hover")).getText());
    }

    @Test
    void theScrubShowsTheStockAfterABlockWhatItRemovedAndTheTool() throws Exception {
        openTheBishop();
        WebElement slider = browser.findElement(By.id("scrub"));
        assertEquals("0", slider.getAttribute("value"));
        slider.click();
        slider.sendKeys(Keys.HOME);
        // the blocks that move, in order: N100 (line 2), N120 (3), N130 (5), N135 (6): the first pass
        for (int i = 0; i < 4; i++) {
            slider.sendKeys(Keys.ARROW_RIGHT);
        }
        wait.until(ExpectedConditions.attributeToBe(By.id("scrubinfo"), "data-line", "6"));
        WebElement scrub = browser.findElement(By.cssSelector("#profile g.scrub"));
        assertEquals("6", scrub.getAttribute("data-line"));
        assertFalse(scrub.findElements(By.cssSelector("polygon.removed")).isEmpty(), "what N135 took off");
        assertFalse(scrub.findElements(By.cssSelector("polygon.left")).isEmpty(), "the stock after it");
        assertFalse(scrub.findElements(By.cssSelector("polygon.insert")).isEmpty(), "the insert where it ended");
        assertTrue(browser.findElement(By.id("profile")).getAttribute("class").contains("scrubbing"));
        assertEquals(6, cursorLine(), "the editor follows the scrub");
        assertTrue(browser.findElement(By.id("scrubinfo")).getText().contains("block 4 of"), browser.findElement(By.id("scrubinfo")).getText());
        // along the pass the stock after it stands where the pass ran (X2034), the stock before it above (the bar's 2200)
        String along = """
                const m = document.querySelector("#profile g.move.feed[data-line='6'] polyline.stroke").getBBox();
                const y = m.y + m.height / 2;
                let at = 0, above = 0;
                for (const p of arguments[0].points) {
                  if (p.x < m.x - 2 || p.x > m.x + m.width + 2) continue;
                  if (Math.abs(p.y - y) < 1.5) at++;
                  else if (p.y < y - 3 && p.x > m.x + 4 && p.x < m.x + m.width - 4) above++; // inside the pass's ends
                }
                return [at, above];""";
        List<?> left = (List<?>) js(along, scrub.findElement(By.cssSelector("polygon.left")));
        List<?> removed = (List<?>) js(along, scrub.findElement(By.cssSelector("polygon.removed")));
        assertTrue(((Number) left.get(0)).intValue() >= 2, "the stock after N135 along its pass: " + left);
        assertEquals(0, ((Number) left.get(1)).intValue(), "nothing above the pass is left: " + left);
        assertTrue(((Number) removed.get(1)).intValue() >= 1, "the stock before N135 stood above the pass: " + removed);
        Browser.screenshot(browser, "scrub");
        slider.sendKeys(Keys.HOME); // back to the finished part
        wait.until(d -> d.findElements(By.cssSelector("#profile g.scrub")).isEmpty());
    }

    @Test
    void configureShowsTheNewFindingBeforeSavingAndThenSaves() throws Exception {
        // a studio of its own: saving a profile changes the machine every later check uses
        Path own = Files.createDirectory(Files.createTempDirectory("gcnc-studio-configure").resolve("programs")); // a plain name on the screen
        Files.copy(Path.of("samples/bishop.nc"), own.resolve("bishop.nc"));
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        try (Studio configured = Studio.start(new Studio.Config(own, 0, s, ErrorMessages.Lang.EN, "test"))) {
            open(configured, "bishop.nc");
            configure(own);
        }
    }

    /** An inch program on the Haas profile (X a diameter; travel in mm of radius in the file). */
    static final String INCH = """
            O1000 (A SHAFT IN INCHES)
            G20 G18 G40 G99
            G50 S2000
            T0101
            G97 S800 M03
            G00 X1.8 Z0.1
            G01 Z-1.5 F0.01
            G00 X2.0
            Z0.1
            G28 U0 W0
            M30
            """;

    /**
     * Configure on an inch program, Haas profile: the fields in inches, X as a diameter, the file's
     * keys and values beside them; a travel typed in inches is saved as its exact millimetres of
     * radius, the untouched end as the file wrote it, and the form shows the same inches again.
     */
    @Test
    void configureShowsAnInchProgramsTermsAndSavesExactMillimetres() throws Exception {
        Path own = Files.createDirectory(Files.createTempDirectory("gcnc-studio-inch").resolve("programs"));
        Files.writeString(own.resolve("shaft.nc"), INCH);
        Session s = Session.open(Session.Options.defaults().withMachine("haas"));
        try (Studio configured = Studio.start(new Studio.Config(own, 0, s, ErrorMessages.Lang.EN, "test"))) {
            open(configured, "shaft.nc");
            // the summary in the program's terms: the part (feed moves) apart from every move's envelope
            wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("summary"),
                    "Part: X 1.8000 … 1.8000 (diameter), Z -1.5000 … 0.1000 in from work zero (feed moves)"));
            browser.findElement(By.id("configure-open")).click();
            wait.until(ExpectedConditions.attributeToBe(By.id("configure"), "data-ready", "true"));
            assertEquals("in", browser.findElement(By.id("configure")).getAttribute("data-units"));
            assertTrue(browser.findElement(By.id("confignote")).getText().startsWith("Lengths in the program's terms: inches, X as a diameter"));
            // x.travel = -4, 212 (mm of radius): -8 and 424 mm of diameter, in inches
            assertEquals("-0.314961", field("x.travel", 0).getAttribute("value"));
            assertEquals("16.692913", field("x.travel", 1).getAttribute("value"));
            assertEquals("x.travel = -4, 212", fileValue("x.travel"));
            assertEquals("-0.787402", field("z.travel", 0).getAttribute("value")); // z.travel = -20, 513: Z is not doubled
            assertEquals("5.905512", field("work.G55", 1).getAttribute("value")); // work.G55 = 0, 150
            assertEquals("0.03126", field("nose.1", 0).getAttribute("value")); // nose.1 = 0.794, 3: a radius
            assertEquals("3", field("nose.1", 1).getAttribute("value"));
            field("x.travel", 0).clear();
            field("x.travel", 0).sendKeys("-0.5");
            // before saving: what the file would hold, exactly (-0.5 in of diameter = -6.35 mm of radius)
            wait.withMessage(() -> fileValue("x.travel") + " / " + browser.findElement(By.id("impactnote")).getText())
                    .until(d -> fileValue("x.travel").equals("x.travel = -4, 212 → x.travel = -6.35, 212"));
            browser.findElement(By.id("configure-save")).click();
            org.openqa.selenium.Alert prompt = wait.until(ExpectedConditions.alertIsPresent());
            prompt.sendKeys("inch.machine");
            prompt.accept();
            wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "profile saved as inch.machine"));
            String written = Files.readString(own.resolve("inch.machine"));
            assertTrue(written.lines().anyMatch(l -> l.matches("x\\.travel = -6\\.35, 212(\\s+#.*)?")), written);
            assertTrue(written.lines().anyMatch(l -> l.matches("z\\.travel = -20, 513(\\s+#.*)?")), "an untouched key as it was");
            gcnc.machine.MachineProfile saved = Session.open(Session.Options.defaults()
                    .withMachine(own.resolve("inch.machine").toString())).profile();
            assertEquals(-6.35, saved.x().min() / saved.x().countsPerMm(), 1e-9);
            // the form again, from the saved file: the same inches, the file's new value beside them
            wait.ignoring(org.openqa.selenium.StaleElementReferenceException.class) // the form is made again after the save
                    .until(d -> fileValue("x.travel").equals("x.travel = -6.35, 212"));
            assertEquals("-0.5", field("x.travel", 0).getAttribute("value"));
            assertEquals("16.692913", field("x.travel", 1).getAttribute("value"));
            Browser.screenshot(browser, "configure-inch");
            browser.findElement(By.id("configure-close")).click();
        }
    }

    private WebElement field(String key, int part) {
        return browser.findElement(By.cssSelector("#configure input[data-key='" + key + "'][data-part='" + part + "']"));
    }

    private String fileValue(String key) {
        return browser.findElement(By.cssSelector("#configure tr[data-key='" + key + "'] td.filevalue")).getText();
    }

    private void configure(Path dir) throws IOException {
        wait.withMessage(() -> "impact: " + browser.findElement(By.id("impactnote")).getText() + " / "
                + browser.findElement(By.id("impact")).getText() + " / status: " + browser.findElement(By.id("status")).getText());
        browser.findElement(By.id("configure-open")).click();
        wait.until(ExpectedConditions.attributeToBe(By.id("configure"), "data-ready", "true"));
        WebElement zMin = browser.findElement(By.cssSelector("#configure input[data-key='z.travel'][data-part='0']"));
        assertEquals("-30000.0008", zMin.getAttribute("value"));
        zMin.clear();
        zMin.sendKeys("-15000");
        // before saving: the passes below -15000 mm become E015, and nothing is written yet
        wait.until(d -> !d.findElements(By.cssSelector("#impact ul.became li[data-line='6'][data-code='E015']")).isEmpty());
        assertTrue(browser.findElement(By.id("impactnote")).getText().contains("before saving"));
        assertFalse(Files.exists(dir.resolve("lathe.machine")));
        assertTrue(browser.findElement(By.id("counts")).getText().contains("no errors"), "the program is still judged by the old profile");
        Browser.screenshot(browser, "configure");

        // a value the loader refuses is marked at its field
        zMin.sendKeys("x");
        wait.until(ExpectedConditions.attributeContains(By.cssSelector("#configure tr[data-key='z.travel']"), "class", "invalid"));
        zMin.sendKeys(Keys.BACK_SPACE);
        wait.until(d -> !d.findElement(By.cssSelector("#configure tr[data-key='z.travel']")).getAttribute("class").contains("invalid"));

        browser.findElement(By.id("configure-save")).click();
        org.openqa.selenium.Alert prompt = wait.until(ExpectedConditions.alertIsPresent());
        prompt.sendKeys("lathe.machine");
        prompt.accept();
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "profile saved as lathe.machine"));
        assertTrue(Files.readString(dir.resolve("lathe.machine")).contains("z.travel = -15000, 880000.88888"));
        // from now on the program is judged with it: its errors appear under the text
        // (the list as drawn now: the check and then the simulation each redraw it)
        wait.ignoring(org.openqa.selenium.StaleElementReferenceException.class).until(d -> d.findElements(
                By.cssSelector("#errors tbody tr.error td")).stream().limit(1).anyMatch(td -> td.getText().equals("E015")));
        assertTrue(browser.findElement(By.id("where")).getText().contains("lathe.machine"));
        // the way back: with the old travel the findings stop being
        WebElement again = browser.findElement(By.cssSelector("#configure input[data-key='z.travel'][data-part='0']"));
        again.clear();
        again.sendKeys("-30000.0008");
        wait.until(d -> !d.findElements(By.cssSelector("#impact ul.gone li[data-line='6']")).isEmpty());
        browser.findElement(By.id("configure-save")).click();
        prompt = wait.until(ExpectedConditions.alertIsPresent());
        prompt.sendKeys("lathe.machine");
        prompt.accept();
        wait.until(ExpectedConditions.alertIsPresent()).accept(); // lathe.machine exists: overwrite it
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "profile saved as lathe.machine"));
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("counts"), "no errors"));
        browser.findElement(By.id("configure-close")).click();
    }

    @Test
    void clickingADmcLinePutsTheCursorOnItsBlock() throws Exception {
        openTheBishop();
        WebElement n145 = browser.findElement(By.cssSelector("#dmc li span[data-source='9']")); // N145 G01 Z-03550
        js("arguments[0].scrollIntoView({block: 'center'})", n145);
        n145.click();
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "9"));
        // and the cursor there lights every DMC command of the block, the clicked one among them, and their lines
        wait.until(d -> n145.getAttribute("class").contains("current"));
        for (WebElement span : browser.findElements(By.cssSelector("#dmc li span.current"))) {
            assertEquals("9", span.getAttribute("data-source"));
        }
        for (WebElement li : browser.findElements(By.cssSelector("#dmc li.current"))) {
            assertFalse(li.findElements(By.cssSelector("span[data-source='9']")).isEmpty(), li.getText());
        }
    }

    @Test
    void clickingThePathOfASubprogramBlockPutsTheCursorOnItsLine() throws Exception {
        Path haasDir = Files.createTempDirectory("gcnc-studio-haas");
        Files.writeString(haasDir.resolve("sub.nc"), String.join("\n",
                "%",
                "O01000 (TWO PASSES THROUGH LOCAL SUBPROGRAMS)",
                "G21 G18 G99",
                "T0101",
                "G50 S2000",
                "G97 S1000 M03",
                "G00 X52. Z2.",
                "M97 P100",
                "G00 X46.",
                "M97 P200",
                "G00 X100. Z100.",
                "M30",
                "N100 G01 Z-20. F0.2", // line 13: run from line 8
                "G00 X52. Z2.",
                "M99",
                "N200 G01 Z-15. F0.2", // line 16: run from line 10
                "G00 X52. Z2.",
                "M99",
                "%", ""));
        Files.writeString(haasDir.resolve("main.nc"), String.join("\n", MAIN) + "\n");
        Files.writeString(haasDir.resolve("O1000.nc"), String.join("\n", O1000) + "\n");
        Session s = Session.open(Session.Options.defaults().withMachine("haas"));
        try (Studio haas = Studio.start(new Studio.Config(haasDir, 0, s, ErrorMessages.Lang.EN, "test"))) {
            open(haas, "sub.nc");
            wait.until(d -> !d.findElements(By.cssSelector("#profile g.move.feed[data-line='16']")).isEmpty());
            for (int line : new int[] {13, 16}) {
                WebElement move = browser.findElement(By.cssSelector("#profile g.move.feed[data-line='" + line + "']"));
                @SuppressWarnings("unchecked")
                List<Number> xy = (List<Number>) js("const r = arguments[0].getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2];", move);
                new Actions(browser).moveToLocation((int) Math.round(xy.get(0).doubleValue()),
                        (int) Math.round(xy.get(1).doubleValue())).click().perform();
                wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", String.valueOf(line)));
                assertTrue(move.getAttribute("class").contains("current"));
            }
            // a subprogram in a file of its own: a click on its pass opens that file at the pass's line
            open(haas, "main.nc");
            WebElement pass = wait.until(d -> d.findElement(By.cssSelector("#profile g.move.feed[data-file='O1000.nc']")));
            assertEquals("3", pass.getAttribute("data-line"));
            @SuppressWarnings("unchecked")
            List<Number> xy = (List<Number>) js("const r = arguments[0].getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2];", pass);
            new Actions(browser).moveToLocation((int) Math.round(xy.get(0).doubleValue()),
                    (int) Math.round(xy.get(1).doubleValue())).click().perform();
            wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("name"), "O1000.nc"));
            wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "3"));
            assertTrue(browser.getCurrentUrl().endsWith("&file=O1000.nc"), browser.getCurrentUrl());
            // its DMC lines too: a click on one in main.nc's DMC opens O1000.nc at the retract's line
            open(haas, "main.nc");
            WebElement retract = wait.until(d -> d.findElement(By.cssSelector("#dmc li span[data-file='O1000.nc'][data-source='4']")));
            js("arguments[0].scrollIntoView({block: 'center'})", retract);
            retract.click();
            wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("name"), "O1000.nc"));
            wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "4"));
        }
    }

    /** A program that calls O1000 (M98 P1000), which is in a file of its own beside it. */
    static final String[] MAIN = {"%", "O01001 (A PASS FROM A SUBPROGRAM IN ITS OWN FILE)", "G21 G18 G99", "T0101", "G50 S2000",
        "G97 S1000 M03", "G00 X46. Z2.", "M98 P1000", "G00 X100. Z100.", "M30", "%"};
    static final String[] O1000 = {"%", "O01000 (ONE PASS)", "G01 Z-20. F0.2", "G00 X52. Z2.", "M99", "%"};
}
