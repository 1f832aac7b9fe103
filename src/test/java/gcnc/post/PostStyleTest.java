package gcnc.post;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import gcnc.post.PostStyleGenerator.Post;
import gcnc.post.PostStyleGenerator.Program;
import gcnc.sim.SimOptions;
import gcnc.sim.StockSize;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * Programs written the way the Fusion 360 turning posts write them ({@link PostStyleGenerator})
 * check clean on the machine they are for (haas; fanuc with control fanuc-a or fanuc-b), and
 * compile and simulate clean from the blank they were written for: the language the posts emit
 * is the language gcnc accepts. The default run is twenty-four seeds on each of the three; {@code
 * gradle junitPlatformTest -Ponly=PostStyle -PpostSeed=1 -PpostCount=5000} runs a long campaign.
 */
class PostStyleTest {
    private static final long SEED = 20261127L;
    private static final long FIRST = Long.getLong("gcnc.post.seed", SEED);
    /** The default run: enough seeds that every settled construct is written on every post that writes it. */
    private static final long DEFAULT_COUNT = 24;
    private static final long COUNT = Long.getLong("gcnc.post.count", DEFAULT_COUNT);
    /** How long the blank is (mm): longer than any part the generator turns, shorter than the stick-out plus the jaws. */
    private static final double BLANK_LENGTH = 120;

    private static final Map<Post, Session> SESSIONS = new EnumMap<>(Post.class);

    private static Session session(Post post) throws Exception {
        Session s = SESSIONS.get(post);
        if (s == null) {
            s = Session.open(Session.Options.defaults().withMachine(post.machine).withControl(post.control));
            SESSIONS.put(post, s);
        }
        return s;
    }

    /**
     * The findings of a program that a post-style program may not have, as "line:code". It may
     * have notes (they say what gcnc's model does differently, such as E622 on a G71 under G42,
     * not that the program is wrong), and E113 on M31/M33 (chip conveyor), which the haas
     * profile's Galil board has no output for, so gcnc says it does nothing, rightly.
     */
    private static List<String> unexpected(Compiler.Result r, String text) {
        String[] lines = text.split("\n", -1);
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            int line = d.span().line();
            String src = line >= 1 && line <= lines.length ? lines[line - 1] : "";
            boolean conveyor = d.code().id().equals("E113") && d.severity() == Severity.WARNING
                    && src.matches(".*M3[13]\\b.*");
            if (!conveyor && d.severity() != Severity.NOTE) {
                out.add(line + ":" + d.code().id() + " " + d.severity() + " " + String.join(", ", d.args()));
            }
        }
        return out;
    }

    private static Compiler.Result check(Post post, String text) throws Exception {
        return session(post).check(new StringReader(text));
    }

    private static Compiler.Result simulate(Program p) throws Exception {
        Session s = session(p.post());
        double stickout = s.profile().model().stock().orElseThrow().stickout();
        SimOptions blank = SimOptions.defaults().withStock(new StockSize(p.part().blank(), BLANK_LENGTH, stickout));
        return s.compile(new StringReader(p.text()), Optional.of(blank), false, line -> { });
    }

    private static String show(Program p) {
        return p.post() + " seed " + p.seed() + " " + p.used() + ":\n" + p.text();
    }

    @TestFactory
    Stream<DynamicTest> postStyleProgramsCheckAndSimulateClean() {
        List<DynamicTest> tests = new ArrayList<>();
        for (long seed = FIRST; seed < FIRST + COUNT; seed++) {
            for (Post post : Post.values()) {
                long s = seed;
                tests.add(dynamicTest(post + " seed " + s, () -> {
                    Program p = PostStyleGenerator.generate(post, s);
                    assertEquals(List.of(), unexpected(check(post, p.text()), p.text()), "check: " + show(p));
                    if (p.used().stream().noneMatch(PostStyleGenerator.SIMULATION_PENDING::contains)) {
                        assertEquals(List.of(), unexpected(simulate(p), p.text()), "simulate: " + show(p));
                    }
                }));
            }
        }
        return tests.stream();
    }

    /** The default run writes every construct that is not pending or unsupported, on every post that writes it, and no other. */
    @Test
    void theDefaultRunWritesEveryConstruct() {
        for (Post post : Post.values()) {
            Set<Construct> seen = EnumSet.noneOf(Construct.class);
            for (long seed = SEED; seed < SEED + DEFAULT_COUNT; seed++) {
                seen.addAll(PostStyleGenerator.generate(post, seed).used());
            }
            for (Construct c : Construct.values()) {
                if (c.on(post)) {
                    assertEquals(PostStyleGenerator.settled().contains(c), seen.contains(c), post + " " + c);
                }
            }
        }
    }

    /**
     * Each pending or not-supported construct, written into an otherwise clean program, still has
     * an error on this branch. When a merge makes one check clean, this
     * fails so that it is taken out of {@link PostStyleGenerator#PENDING} (or NOT_SUPPORTED) and
     * the campaign writes it.
     */
    @TestFactory
    Stream<DynamicTest> pendingConstructsDoNotCheckCleanYet() {
        List<DynamicTest> tests = new ArrayList<>();
        Set<Construct> settled = PostStyleGenerator.settled();
        Set<Construct> waiting = EnumSet.copyOf(PostStyleGenerator.PENDING);
        waiting.addAll(PostStyleGenerator.NOT_SUPPORTED);
        for (Construct c : waiting) {
            for (Post post : Post.values()) {
                if (!c.on(post)) {
                    continue;
                }
                tests.add(dynamicTest(c + " on " + post, () -> {
                    Set<Construct> forced = EnumSet.of(c);
                    forced.addAll(c.needs());
                    Program p = PostStyleGenerator.generate(post, SEED, settled, forced);
                    assertTrue(p.used().contains(c), "the generator wrote " + c);
                    List<String> found = unexpected(check(post, p.text()), p.text());
                    assertFalse(found.isEmpty(), c + " checks clean on " + post
                            + " now: take it out of PostStyleGenerator.PENDING\n" + show(p));
                }));
            }
        }
        return tests.stream();
    }

    /** The harness sees a fault: the facing cut turned into a rapid is a rapid into the blank (E305) on its line. */
    @Test
    void aRapidIntoTheBlankIsFound() throws Exception {
        for (Post post : Post.values()) {
            Program p = PostStyleGenerator.generate(post, SEED);
            String[] lines = p.text().split("\n", -1);
            int facing = -1;
            for (int i = 0; i < lines.length && facing < 0; i++) {
                if (lines[i].matches("(N\\d+ ?)?G0?1 ?X-.*")) {
                    facing = i;
                }
            }
            assertTrue(facing > 0, "a facing cut in\n" + p.text());
            lines[facing] = lines[facing].replaceFirst("G0?1", "G0").replaceAll(" ?F\\S+", "");
            Program bad = new Program(post, p.seed(), String.join("\n", lines), p.part(), p.used());
            List<String> found = unexpected(simulate(bad), bad.text());
            String at = (facing + 1) + ":E305";
            assertTrue(found.stream().anyMatch(f -> f.startsWith(at)), found + "\n" + bad.text());
        }
    }
}
