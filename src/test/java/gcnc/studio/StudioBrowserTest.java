package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.dmc.SourceMap;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.openqa.selenium.By;
import org.openqa.selenium.Keys;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.support.ui.ExpectedConditions;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * The studio in a real browser (headless Chromium, the test JVM's one: {@link Browser#shared}), on a copy of the bishop
 * (samples/bishop.nc, machine thesis-2004): what a user does, and what they must then see. Each
 * screen is saved as a PNG under docs/studio/ for docs/studio.md.
 */
class StudioBrowserTest {
    static WebDriver browser;
    static Studio studio;
    static Path dir;
    WebDriverWait wait;

    @BeforeAll
    static void start() throws Exception {
        browser = Browser.shared();
        // a folder with a plain name: the page shows it, and the screenshots should not change with it
        dir = Files.createDirectory(Files.createTempDirectory("gcnc-studio-browser").resolve("programs"));
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test"));
    }

    @AfterAll
    static void stop() {
        Browser.release(browser, studio);
    }

    @BeforeEach
    void openTheBishop() throws Exception {
        for (String f : new String[] {"bishop.nc", "bishop.dmc", "bishop.dmc.map", "copy.nc", "other.nc"}) {
            Files.deleteIfExists(dir.resolve(f));
        }
        Files.copy(Path.of("samples/bishop.nc"), dir.resolve("bishop.nc"));
        Files.writeString(dir.resolve("other.nc"), "M30\n");
        wait = Browser.waitUpTo(browser, Duration.ofSeconds(45)); // a shared, busy machine: a first simulation can take a while
        browser.get("about:blank"); // leaves the last test's page (an unsaved edit there would ask first)
        dismissAnyAlert();
        browser.get(studio.url("bishop.nc").toString());
        wait.until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-ready", "true"));
        // checked and simulated: the error list says so, and the DMC is there
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("counts"), "no errors"));
        int lines = bishopDmcLines(); // what a compile of the same program writes, line for line
        wait.until(d -> d.findElements(By.cssSelector("#dmc li")).size() == lines);
    }

    private void dismissAnyAlert() {
        try {
            browser.switchTo().alert().accept();
        } catch (org.openqa.selenium.NoAlertPresentException e) {
            // none
        }
    }

    /** Puts the cursor at the end of a line, with the keyboard, as a user would. */
    private WebElement endOfLine(int line) {
        WebElement content = browser.findElement(By.cssSelector(".cm-content"));
        content.click();
        content.sendKeys(Keys.chord(Keys.CONTROL, Keys.HOME));
        // the same key presses one by one, in one command to the driver (one round trip, not one a key)
        content.sendKeys(Keys.ARROW_DOWN.toString().repeat(line - 1) + Keys.END);
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", String.valueOf(line)));
        return content;
    }

    private List<WebElement> errorRows() {
        return browser.findElements(By.cssSelector("#errors tbody tr"));
    }

    /**
     * The cells of the error list's one row, once it is {@code code}'s: read in one go inside a wait,
     * since every check (each key typed, the simulation after it) redraws the list and a row found a
     * moment ago may be gone or another's.
     */
    private List<String> onlyError(String code) {
        return wait.ignoring(org.openqa.selenium.StaleElementReferenceException.class).until(d -> {
            List<WebElement> rows = errorRows();
            List<String> cells = rows.size() != 1 ? List.of()
                    : rows.get(0).findElements(By.tagName("td")).stream().map(WebElement::getText).toList();
            return !cells.isEmpty() && cells.get(0).equals(code) ? cells : null;
        });
    }

    /** Waits until the program list, as drawn now, has {@code name} chosen (a folder's change event redraws it). */
    private void waitChosen(String name) {
        wait.ignoring(org.openqa.selenium.StaleElementReferenceException.class).until(d ->
                name.equals(new Select(d.findElement(By.id("files"))).getFirstSelectedOption().getText()));
    }

    private int cursorLine() {
        return Integer.parseInt(browser.findElement(By.id("cursor")).getAttribute("data-line"));
    }

    @Test
    void aBrokenLineGetsItsDiagnosticUnderItAndLosesItWhenFixed() throws IOException {
        WebElement content = endOfLine(6); // N135 G01 Z-04500
        content.sendKeys(" Q");
        List<String> cells = onlyError("E006");
        assertEquals("E006", cells.get(0));
        assertEquals("expecting a number for parameter Q", cells.get(1));
        assertEquals("6", cells.get(2));
        assertEquals("18", cells.get(3));
        // underlined on its own line, and marked in the gutter
        WebElement sixth = browser.findElements(By.cssSelector(".cm-content .cm-line")).get(5);
        wait.until(d -> !sixth.findElements(By.cssSelector(".cm-lintRange-error")).isEmpty());
        assertEquals("Q", sixth.findElement(By.cssSelector(".cm-lintRange-error")).getText());
        assertEquals(1, browser.findElements(By.cssSelector(".cm-lint-marker-error")).size());
        assertTrue(browser.findElement(By.id("counts")).getText().contains("1 error"));
        // no DMC and no path for a program with an error: the last ones stay, greyed and said to be old
        wait.until(ExpectedConditions.attributeContains(By.id("path"), "class", "stale"));
        assertTrue(browser.findElement(By.id("pathnote")).getText().contains("last version without errors"));
        // the DMC pane says why it has no DMC of this text, and the summary does not say "DMC lines: 0"
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("dmcnote"),
                "no DMC: the program has 1 error (the first at line 6); nothing is translated after it"));
        assertTrue(browser.findElement(By.id("galil")).getAttribute("class").contains("stale"));
        assertTrue(browser.findElement(By.id("summary")).getText().contains("DMC lines: no DMC: the program has 1 error"),
                browser.findElement(By.id("summary")).getText());
        Browser.screenshot(browser, "diagnostics");

        content.sendKeys(Keys.BACK_SPACE, Keys.BACK_SPACE);
        wait.until(d -> errorRows().isEmpty() && d.findElements(By.cssSelector(".cm-lintRange-error")).isEmpty());
        assertTrue(browser.findElement(By.id("counts")).getText().contains("no errors"));
        wait.until(d -> !d.findElement(By.id("path")).getAttribute("class").contains("stale"));
        wait.until(ExpectedConditions.textToBe(By.id("dmcnote"), ""));
        assertEquals(Files.readString(Path.of("samples/bishop.nc")), Files.readString(dir.resolve("bishop.nc")),
                "typing saves nothing");
    }

    /**
     * N145's cut made a rapid (line 9: G01 to G00): the check finds nothing, the simulator an E305 on
     * the bar. The error list has it as soon as the text is simulated, no Compile pressed, with its
     * code, line and message, counted in the heading and underlined; a click selects its line and
     * marks its place on the path; the DMC pane says why it has none.
     */
    @Test
    void aSimulatorFindingIsInTheErrorListWithoutCompileAndAClickShowsItsPlace() throws IOException {
        WebElement content = endOfLine(9); // N145 G01 Z-03550
        content.sendKeys(Keys.HOME, Keys.ARROW_RIGHT, Keys.ARROW_RIGHT, Keys.ARROW_RIGHT, Keys.ARROW_RIGHT, Keys.ARROW_RIGHT,
                Keys.ARROW_RIGHT, Keys.DELETE, Keys.DELETE, "00");
        wait.until(d -> d.findElement(By.cssSelector(".cm-content")).getText().contains("N145 G00 Z-03550"));
        wait.until(d -> errorRows().size() == 1 && !errorRows().get(0).getAttribute("class").contains("pending"));
        WebElement row = errorRows().get(0);
        List<WebElement> cells = row.findElements(By.tagName("td"));
        assertEquals("E305", cells.get(0).getText());
        assertTrue(cells.get(1).getText().startsWith("rapid move enters the blank at X1984. Z-1775. (N145;"), cells.get(1).getText());
        assertEquals("9", cells.get(2).getText());
        assertTrue(row.getAttribute("class").contains("error") && row.getAttribute("class").contains("simulator"));
        assertEquals("— 1 error, 0 warnings", browser.findElement(By.id("counts")).getText());
        // underlined in the text too, as the check's findings are
        WebElement ninth = browser.findElements(By.cssSelector(".cm-content .cm-line")).get(8);
        wait.until(d -> !ninth.findElements(By.cssSelector(".cm-lintRange-error")).isEmpty());
        // no DMC for a program with an error, and the pane says why
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("dmcnote"),
                "no DMC: the simulation found 1 error (the first at line 9)"));
        assertTrue(browser.findElement(By.id("summary")).getText().contains("DMC lines: no DMC: the simulation found 1 error"));
        assertFalse(Files.exists(dir.resolve("bishop.dmc")), "nothing compiled");
        // a click: the cursor on line 9, its moves lit on the path, and the finding's place marked
        browser.findElement(By.cssSelector(".cm-content")).sendKeys(Keys.chord(Keys.CONTROL, Keys.HOME));
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "1"));
        assertTrue(browser.findElements(By.cssSelector("#profile circle.mark.picked")).isEmpty());
        errorRows().get(0).click();
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "9"));
        WebElement mark = browser.findElement(By.cssSelector("#profile circle.mark.picked"));
        assertEquals("E305", mark.getAttribute("data-code"));
        assertEquals("9", mark.getAttribute("data-line"));
        assertFalse(browser.findElements(By.cssSelector("#profile g.move.current[data-line='9']")).isEmpty());
    }

    @Test
    void clickingADiagnosticPutsTheCursorOnItsLine() {
        endOfLine(46).sendKeys(" Q"); // N340 G01 X+1034 Z-01600
        wait.until(d -> errorRows().size() == 1);
        browser.findElement(By.cssSelector(".cm-content")).sendKeys(Keys.chord(Keys.CONTROL, Keys.HOME));
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "1"));
        wait.ignoring(org.openqa.selenium.StaleElementReferenceException.class).until(d -> {
            errorRows().get(0).click();
            return true;
        });
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "46"));
        assertEquals("Line 46, column 25", browser.findElement(By.id("cursor")).getText());
    }

    @Test
    void clickingThePathPutsTheCursorOnItsBlock() throws IOException {
        WebElement n135 = browser.findElement(By.cssSelector("#profile g.move.feed[data-line='6']"));
        clickMiddleOf(n135);
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "6"));
        assertTrue(n135.getAttribute("class").contains("current"));
        WebElement n145 = browser.findElement(By.cssSelector("#profile g.move.feed[data-line='9']")); // N145 G01 Z-03550
        clickMiddleOf(n145);
        wait.until(ExpectedConditions.attributeToBe(By.id("cursor"), "data-line", "9"));
        assertFalse(n135.getAttribute("class").contains("current"));
        Browser.screenshot(browser, "toolpath");
    }

    /**
     * A mouse click at the middle of a move as drawn (a straight move along Z has no height, which
     * Selenium's element click refuses): whatever the page has on top at that pixel gets it.
     */
    private void clickMiddleOf(WebElement move) {
        @SuppressWarnings("unchecked")
        List<Number> xy = (List<Number>) ((org.openqa.selenium.JavascriptExecutor) browser).executeScript(
                "const r = arguments[0].getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2];", move);
        new org.openqa.selenium.interactions.Actions(browser)
                .moveToLocation((int) Math.round(xy.get(0).doubleValue()), (int) Math.round(xy.get(1).doubleValue())).click().perform();
    }

    @Test
    void theCursorOnABlockLightsItsDmcLinesAndItsMoves() throws IOException {
        endOfLine(6);
        wait.until(d -> !d.findElements(By.cssSelector("#dmc li.current")).isEmpty());
        List<String> lit = new ArrayList<>();
        for (WebElement span : browser.findElements(By.cssSelector("#dmc li span.current"))) {
            assertEquals("6", span.getAttribute("data-source"));
            lit.add(span.getText());
        }
        // the same DMC lines the command line's .map gives line 6
        StudioServerTest.cli("compile", "--machine", "thesis-2004", dir.resolve("bishop.nc").toString(), "-o",
                dir.resolve("bishop.dmc").toString());
        List<String> dmc = Files.readAllLines(dir.resolve("bishop.dmc"));
        SourceMap.Locator map;
        try (var in = Files.newBufferedReader(dir.resolve("bishop.dmc.map"))) {
            map = SourceMap.read(in).at();
        }
        // the commands of the packed lines that the map gives line 6
        List<String> expected = new ArrayList<>();
        for (int i = 1; i <= dmc.size(); i++) {
            List<String> commands = gcnc.dmc.DmcReader.statements(dmc.get(i - 1));
            for (int k = 0; k < commands.size(); k++) {
                gcnc.dmc.Source at = map.source(i, k);
                if (at != null && at.line() == 6) {
                    expected.add(commands.get(k));
                }
            }
        }
        assertFalse(expected.isEmpty());
        assertEquals(expected, lit);
        List<WebElement> moves = browser.findElements(By.cssSelector("#profile g.move.current"));
        assertEquals(1, moves.size());
        assertEquals("6", moves.get(0).getAttribute("data-line"));
        Browser.screenshot(browser, "galil");
    }

    @Test
    void compileWritesTheDmcAndItsMapBesideTheProgram() throws IOException {
        endOfLine(6).sendKeys(" (pass 1)"); // an unsaved edit: compile saves it first
        browser.findElement(By.id("compile")).click();
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "compiled: wrote bishop.dmc and bishop.dmc.map"));
        assertTrue(Files.readString(dir.resolve("bishop.nc")).contains("N135 G01 Z-04500 (pass 1)"));
        Path cli = Files.createTempDirectory("gcnc-cli").resolve("bishop.dmc");
        StudioServerTest.cli("compile", "--machine", "thesis-2004", dir.resolve("bishop.nc").toString(), "-o", cli.toString());
        assertEquals(Files.readString(cli), Files.readString(dir.resolve("bishop.dmc")));
        assertEquals(Files.readString(Path.of(cli + ".map")), Files.readString(dir.resolve("bishop.dmc.map")));
        String summary = browser.findElement(By.id("summary")).getText();
        assertTrue(summary.contains("Cycle time: 34.8 s"), summary); // with the 2 s wait for the spindle after M03
        Browser.screenshot(browser, "compile");
    }

    @Test
    void aFailedSaveKeepsTheEditAndSaysWhy() throws IOException {
        WebElement content = endOfLine(6);
        content.sendKeys(" (mine)");
        content.sendKeys(Keys.chord(Keys.CONTROL, "s"));
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "saved bishop.nc"));
        assertTrue(Files.readString(dir.resolve("bishop.nc")).contains("Z-04500 (mine)\n"));
        // someone else changes the file; our next save must not silently overwrite it, nor lose our edit
        Files.writeString(dir.resolve("bishop.nc"), "(theirs)\nM30\n");
        // found again: the folder's change event may redraw the page's elements meanwhile
        endOfLine(6).sendKeys(" (more)");
        browser.findElement(By.id("save")).click();
        wait.until(ExpectedConditions.alertIsPresent()).dismiss(); // "changed on disk. Overwrite it?" No.
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "not saved: bishop.nc changed on disk"));
        assertEquals("(theirs)\nM30\n", Files.readString(dir.resolve("bishop.nc")));
        assertTrue(browser.findElement(By.cssSelector(".cm-content")).getText().contains("N135 G01 Z-04500 (mine) (more)"));
        assertTrue(browser.findElement(By.id("name")).getText().endsWith("•"), "still marked unsaved");
        Browser.screenshot(browser, "save-failed");

        // opening another program with unsaved changes asks first; "no" keeps everything. The folder's
        // change event may redraw the list while the option is chosen: chosen again from the new list,
        // unless the question is already up (the choice was made before the redraw)
        wait.ignoring(org.openqa.selenium.StaleElementReferenceException.class).until(d -> {
            try {
                d.switchTo().alert();
                return true;
            } catch (org.openqa.selenium.NoAlertPresentException none) {
                new Select(d.findElement(By.id("files"))).selectByValue("other.nc");
                return true;
            }
        });
        wait.until(ExpectedConditions.alertIsPresent()).dismiss();
        assertTrue(browser.findElement(By.cssSelector(".cm-content")).getText().contains("(mine) (more)"));
        waitChosen("bishop.nc");
    }

    @Test
    void saveAsWritesACopyAndOpensIt() throws IOException {
        endOfLine(6).sendKeys(" (copy)");
        browser.findElement(By.id("saveas")).click();
        org.openqa.selenium.Alert prompt = wait.until(ExpectedConditions.alertIsPresent());
        prompt.sendKeys("copy.nc");
        prompt.accept();
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "saved copy.nc"));
        assertTrue(Files.readString(dir.resolve("copy.nc")).contains("Z-04500 (copy)\n"));
        assertEquals(Files.readString(Path.of("samples/bishop.nc")), Files.readString(dir.resolve("bishop.nc")));
        assertTrue(browser.getCurrentUrl().endsWith("&file=copy.nc"), browser.getCurrentUrl());
        waitChosen("copy.nc"); // the list redrawn by the save, and again by the folder's change event
    }

    @Test
    void aNewProgramIsCheckedAsTypedAndMadeOnSave() throws IOException {
        browser.findElement(By.id("new")).click();
        org.openqa.selenium.Alert prompt = wait.until(ExpectedConditions.alertIsPresent());
        prompt.sendKeys("fresh.nc");
        prompt.accept();
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("name"), "fresh.nc •"));
        WebElement content = browser.findElement(By.cssSelector(".cm-content"));
        content.click();
        content.sendKeys("G00 X+2234 Z+00100");
        assertEquals("E052", onlyError("E052").get(0)); // the thesis's programs end with M30
        content.sendKeys(Keys.ENTER, "M30");
        wait.until(d -> errorRows().isEmpty());
        assertFalse(Files.exists(dir.resolve("fresh.nc")), "nothing is written before Save");
        content.sendKeys(Keys.chord(Keys.CONTROL, "s"));
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("status"), "saved fresh.nc"));
        assertEquals("G00 X+2234 Z+00100\nM30", Files.readString(dir.resolve("fresh.nc")));
        Files.delete(dir.resolve("fresh.nc"));
    }

    @Test
    void inSpanishThePageAndTheMessagesAreSpanish() throws Exception {
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        try (Studio es = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.ES, "test"))) {
            browser.get(es.url("bishop.nc").toString());
            wait.until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-ready", "true"));
            wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("counts"), "sin errores"));
            endOfLine(6).sendKeys(" Q");
            wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("dmcnote"),
                    "sin DMC: el programa tiene 1 error (el primero en la línea 6)"));
            String message = onlyError("E006").get(1);
            assertFalse(message.equals("expecting a number for parameter Q"), message);
            assertTrue(message.contains("Q"), message);
            assertEquals("Errores", browser.findElement(By.cssSelector("#problems h2 span")).getText());
            assertEquals("Compilar", browser.findElement(By.id("compile")).getText());
            Browser.screenshot(browser, "spanish");
        }
    }

    /** {@link #bishopDmcLines}, compiled once for the test JVM (samples/bishop.nc does not change during a run). */
    private static int bishopDmcLines;

    /** The lines of the bishop's DMC on thesis-2004, as the session every front end goes through compiles and packs it. */
    static synchronized int bishopDmcLines() throws Exception {
        if (bishopDmcLines == 0) {
            bishopDmcLines = compiledBishopDmcLines();
        }
        return bishopDmcLines;
    }

    private static int compiledBishopDmcLines() throws Exception {
        gcnc.Session s = gcnc.Session.open(gcnc.Session.Options.defaults().withMachine("thesis-2004"));
        int[] n = {0};
        gcnc.dmc.LinePacker packer = new gcnc.dmc.LinePacker(s.profile().controllerLimits().lineWidth(), l -> n[0]++);
        try (java.io.Reader in = Files.newBufferedReader(Path.of("samples/bishop.nc"))) {
            s.compile(in, java.util.Optional.of(s.simulation()), false, packer);
        }
        packer.flush();
        return n[0];
    }
}
