package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.tables.ErrorMessages;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashSet;
import java.util.Set;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.openqa.selenium.By;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.support.ui.ExpectedConditions;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * Run (MEMORY mode) in headless Chromium: the bishop (machine thesis-2004) armed and run on the studio's
 * virtual controller, the live display following it (the executing block lit in the text and on the
 * path, the position), a feed hold that holds and a resume; a stop, and the resume it offers at the
 * exact block. The virtual controller runs five times faster than real time. The Run screen is saved
 * as docs/studio/run.png.
 */
class StudioRunBrowserTest {
    static WebDriver browser;
    static Studio studio;
    static Path dir;
    WebDriverWait wait;

    @BeforeAll
    static void start() throws Exception {
        browser = Browser.shared();
        dir = Files.createDirectory(Files.createTempDirectory("gcnc-studio-run").resolve("programs"));
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test", new Studio.Running(5, null)));
    }

    @AfterAll
    static void stop() {
        Browser.release(browser, studio);
    }

    @BeforeEach
    void openTheBishopsRunScreen() throws Exception {
        Files.deleteIfExists(dir.resolve("bishop.nc"));
        Files.copy(Path.of("samples/bishop.nc"), dir.resolve("bishop.nc"));
        wait = Browser.waitUpTo(browser, Duration.ofSeconds(60)); // a shared, busy machine
        browser.get(studio.url("bishop.nc").toString());
        wait.until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-ready", "true"));
        wait.until(ExpectedConditions.textToBePresentInElementLocated(By.id("counts"), "no errors"));
        wait.until(d -> !d.findElements(By.cssSelector("#profile g.move")).isEmpty());
        browser.findElement(By.id("run-open")).click();
        wait.until(ExpectedConditions.visibilityOfElementLocated(By.id("run")));
    }

    /** Waits for the Run screen's state; a timeout says what the screen showed. */
    private void waitFor(String state) {
        try {
            wait.until(ExpectedConditions.attributeToBe(By.id("run-state"), "data-state", state));
        } catch (org.openqa.selenium.TimeoutException e) {
            throw new AssertionError("no " + state + ": status '" + browser.findElement(By.id("status")).getText() + "', "
                    + browser.findElement(By.id("run-state")).getText() + "\n" + browser.findElement(By.id("runarmed")).getText()
                    + "\n" + browser.findElement(By.id("runlog")).getText(), e);
        }
    }

    private void arm() {
        assertTrue(browser.findElement(By.id("run-start")).getAttribute("disabled") != null, "nothing moves before an arm");
        browser.findElement(By.id("run-arm")).click();
        waitFor("armed");
        String armed = browser.findElement(By.id("runarmed")).getText();
        // what will move, on what, and what pre-flight found: before anything moves
        assertTrue(armed.contains("Program: bishop.nc, 59 blocks"), armed); // the compile's count (gcnc check: 59 blocks)
        assertTrue(armed.contains("DMC1700 Rev 1.0h"), armed);
        // the program form (the bishop fits the DMC-1700's 2,000 lines), as many lines as the compile wrote
        java.util.regex.Matcher lines = java.util.regex.Pattern.compile("(\\d+) DMC lines, about .*, program form").matcher(armed);
        assertTrue(lines.find(), armed);
        assertTrue(armed.contains("Pre-flight: DMC1700, " + lines.group(1) + " of 2000 program lines"), armed);
        // homed: where the simulator verified the program from, in program terms, then the counts
        assertTrue(java.util.regex.Pattern.compile("axes at X-?[0-9.]+ Z-?[0-9.]+ \\(Galil counts 0,0\\)").matcher(armed).find(),
                armed);
        assertTrue(armed.contains("read back identical"), armed);
    }

    /** How many status events the page has shown (the display's counter). */
    private int statusCount() {
        return Integer.parseInt(browser.findElement(By.id("dro")).getAttribute("data-polls"));
    }

    /** The line the text lights as executing (the editor's line number), or 0. */
    private int litInText() {
        Object n = ((org.openqa.selenium.JavascriptExecutor) browser).executeScript("""
                const l = document.querySelector('.cm-content .cm-running');
                return l ? [...document.querySelectorAll('.cm-content .cm-line')].indexOf(l) + 1 : 0;""");
        return ((Number) n).intValue();
    }

    private int litOnPath() {
        var g = browser.findElements(By.cssSelector("#profile g.move.running"));
        return g.isEmpty() ? 0 : Integer.parseInt(g.get(0).getAttribute("data-line"));
    }

    @Test
    void armRunToTheEndWithTheDisplayFollowingAndAHoldThatHolds() throws Exception {
        arm();
        browser.findElement(By.id("run-start")).click();
        // the display follows: the executing block lit in the text and on the path, the same one, and it changes
        Set<Integer> seen = new LinkedHashSet<>();
        wait.until(d -> {
            int text = litInText();
            if (text > 0 && text == litOnPath()) {
                seen.add(text);
            }
            return seen.size() >= 3;
        });
        String x = browser.findElement(By.id("dro-x")).getText();
        assertFalse(x.equals("—"), "the position in program coordinates is shown");
        assertFalse(browser.findElement(By.id("dro-block")).getText().equals("—"));
        Browser.screenshot(browser, "run");
        // feed hold: held, and the axes stay where they are
        browser.findElement(By.id("run-hold")).click();
        waitFor("held");
        Thread.sleep(600); // the deceleration (VD) at five times real time ends well inside this
        String at = browser.findElement(By.id("dro-x")).getText() + " " + browser.findElement(By.id("dro-z")).getText();
        Thread.sleep(800);
        assertEquals(at, browser.findElement(By.id("dro-x")).getText() + " " + browser.findElement(By.id("dro-z")).getText(),
                "a feed hold holds");
        assertTrue(browser.findElement(By.id("run-hold")).getAttribute("disabled") != null);
        // a page opened (or reloaded) during the run finds it: the Run screen open, held, the block lit
        int held = litInText();
        browser.navigate().refresh();
        wait.until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-ready", "true"));
        waitFor("held");
        wait.until(d -> litInText() == held && litOnPath() == held);
        assertEquals(at, browser.findElement(By.id("dro-x")).getText() + " " + browser.findElement(By.id("dro-z")).getText());
        browser.findElement(By.id("run-resume")).click();
        waitFor("running");
        wait.until(d -> !(d.findElement(By.id("dro-x")).getText() + " " + d.findElement(By.id("dro-z")).getText()).equals(at));
        waitFor("finished");
        // the last block (N470, line 59) was the last one lit, and the tool stands at its end point
        assertEquals(59, litInText());
        wait.until(d -> d.findElement(By.id("run-arm")).isEnabled());
        assertTrue(browser.findElement(By.id("run-start")).getAttribute("disabled") != null, "a run needs a new arm");
    }

    /**
     * The run's events come over the event stream, the answer to Start over its own request: a run
     * can end before its start is answered (a short program, a busy machine). Here the page's answer
     * to POST /api/run/start is held until the page has shown FINISHED; the page must then still say
     * FINISHED, not RUNNING, and be ready for a new arm.
     */
    @Test
    void aRunThatEndsBeforeItsStartIsAnsweredStaysFinished() {
        arm();
        js("""
                window.startAnswered = false;
                const real = window.fetch;
                window.fetch = async (url, init) => {
                  const answer = await real(url, init);
                  if (!String(url).endsWith('/api/run/start')) return answer;
                  const box = document.getElementById('run-state');
                  await new Promise((resolve) => {
                    if (box.dataset.state === 'finished') return resolve();
                    new MutationObserver((_, o) => { if (box.dataset.state === 'finished') { o.disconnect(); resolve(); } })
                      .observe(box, { attributes: true });
                  });
                  window.startAnswered = true;
                  return answer;
                };""");
        browser.findElement(By.id("run-start")).click();
        wait.until(d -> Boolean.TRUE.equals(js("return window.startAnswered;")));
        wait.until(d -> d.findElement(By.id("run-arm")).isEnabled()); // the run's thread ended (run-ended)
        assertEquals("finished", browser.findElement(By.id("run-state")).getAttribute("data-state"));
        assertTrue(browser.findElement(By.id("run-state")).getText().startsWith("FINISHED: ran to the end in"),
                browser.findElement(By.id("run-state")).getText());
        assertTrue(browser.findElement(By.id("run-stop")).getAttribute("disabled") != null, "nothing to stop");
        assertFalse(browser.findElement(By.id("status")).getText().startsWith("running"), browser.findElement(By.id("status")).getText());
    }

    private Object js(String script) {
        return ((org.openqa.selenium.JavascriptExecutor) browser).executeScript(script);
    }

    @Test
    void aStopSaysWhereAndTheResumeArmsAtThatBlock() {
        arm();
        browser.findElement(By.id("run-start")).click();
        wait.until(d -> litInText() >= 8);
        // the operator holds, then stops; the resume then also starts with the feed back on (VR left at 0 by
        // the hold would keep the resumed run standing still)
        browser.findElement(By.id("run-hold")).click();
        waitFor("held");
        int polls = statusCount();
        wait.until(d -> statusCount() >= polls + 3);
        browser.findElement(By.id("run-stop")).click();
        waitFor("stopped");
        String where = browser.findElement(By.id("runstopped")).getText();
        int executing = Integer.parseInt(browser.findElement(By.id("dro")).getAttribute("data-line"));
        assertTrue(where.contains("executing: line " + executing), where);
        assertTrue(where.matches("(?s).*\\nAxes at X-?[0-9.]+ Z-?[0-9.]+ \\(Galil counts -?\\d+,-?\\d+\\)\\n.*"), where);
        assertTrue(where.contains("--resume-at " + executing), where); // the command line that does the same
        assertTrue(browser.findElement(By.id("runlog")).getText().contains("E828"), browser.findElement(By.id("runlog")).getText());
        wait.until(d -> d.findElement(By.id("run-resumeat")).isEnabled()); // once the stopped run's thread ended
        browser.findElement(By.id("run-resumeat")).click();
        waitFor("armed");
        assertTrue(browser.findElement(By.id("runarmed")).getText().contains("from line " + executing),
                browser.findElement(By.id("runarmed")).getText());
        browser.findElement(By.id("run-start")).click();
        waitFor("finished");
        assertEquals(59, litInText());
    }
}
