package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.diag.Span;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.parse.BlockReader;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The programs M98 can call, as a control holds them in its memory: those written after the main
 * program's end in its file, and files beside it named after the number ({@code O1000.nc},
 * {@code 1000.nc}; P100 also {@code O0100.nc}, {@code 0100.nc}), read when first called. Every
 * block held counts towards one limit, {@link ProgramFlow#HOLD_LIMIT}.
 */
public final class Library {
    private final Map<Integer, Program> programs = new LinkedHashMap<>();
    private final Set<Integer> called = new LinkedHashSet<>();
    /** Numbers looked for beside the file and not found (looked for once). */
    private final Set<Integer> missing = new LinkedHashSet<>();
    /** Every file beside the program a call looked for, found or not (in the order looked for). */
    private final Set<Path> lookedFor = new LinkedHashSet<>();
    private final Optional<Path> folder;
    private final Diagnostics diags;
    private final int limit;
    /** The control has macro B: a called file's macro lines are read as such. */
    private final boolean macros;
    /** The control's comments end at their line's end ({@link BlockReader#forControl}). */
    private final boolean lineComments;
    private int held;

    Library(Optional<Path> folder, Diagnostics diags, int limit, boolean macros, boolean lineComments) {
        this.lineComments = lineComments;
        this.folder = folder;
        this.macros = macros;
        this.diags = diags;
        this.limit = limit;
    }

    /** The most blocks held. */
    int limit() {
        return limit;
    }

    /** How many more blocks may be held. */
    int room() {
        return limit - held;
    }

    /** A program written after the main program's end (two with one number: E142 at the second). */
    void add(Program p) {
        held += p.blocks().size();
        Program before = programs.putIfAbsent(p.number(), p);
        if (before != null) {
            diags.report(Diagnostic.error(Code.E142_DUPLICATE_PROGRAM, p.start(), p.name(), before.start().line())
                    .in(p.origin()));
        }
    }

    /**
     * The program a call names, or null after reporting why there is none: not in the file nor
     * beside it (E130, E131 at {@code at}), too long to hold (E137), or unreadable (E500).
     */
    Program find(long number, Word at, Span call, Origin caller) throws IOException {
        Program p = number >= 0 && number <= Integer.MAX_VALUE ? programs.get((int) number) : null;
        if (p == null && folder.isPresent() && number >= 0 && number <= 99_999 && !missing.contains((int) number)) {
            p = beside((int) number, call, caller);
            if (p == null && !missing.contains((int) number)) {
                return null; // reported while reading
            }
        }
        if (p == null) {
            if (folder.isEmpty()) {
                diags.error(Code.E130_NO_PROGRAM_HERE, at.span(), Program.name(number));
            } else {
                diags.error(Code.E131_NO_PROGRAM_BESIDE, at.span(), Program.name(number),
                        String.join(" / ", names(number)));
            }
            return null;
        }
        called.add(p.number());
        return p;
    }

    /** The file beside the program named after {@code number}, read whole; null if there is none (or after E137, E500). */
    private Program beside(int number, Span call, Origin caller) throws IOException {
        Path dir = folder.get();
        for (String name : names(number)) {
            lookedFor.add(dir.resolve(name));
        }
        java.util.Optional<Path> found = fileFor(dir, number);
        if (found.isPresent()) {
            return read(number, found.get(), call, caller);
        }
        for (String name : names(number)) {
            Path file = dir.resolve(name);
            if (Files.exists(file)) {
                // there is something by that name, but not a program file: say so rather than "there is no file"
                diags.error(Code.E505_CALLED_NOT_A_FILE, call, Program.name(number), file.toString());
                return null;
            }
        }
        missing.add(number);
        return null;
    }

    /**
     * The program in {@code file}, read whole: the parser's findings are placed in that file, and
     * then again where the caller's blocks come from ({@code caller}).
     */
    private Program read(int number, Path file, Span call, Origin caller) {
        String shown = file.toString();
        List<RawBlock> blocks = new ArrayList<>();
        Span start = Span.of(1, 1);
        diags.placeIn(Origin.file(shown));
        try (Reader in = new gcnc.parse.BoundedReader(open(file), diags, Origin.file(shown))) {
            BlockReader reader = BlockReader.forControl(in, diags, macros, lineComments, Origin.file(shown));
            for (RawBlock b = reader.next(); b != null; b = reader.next()) {
                if (held + blocks.size() >= limit) {
                    diags.placeIn(caller);
                    diags.error(Code.E137_TOO_LONG_TO_HOLD, call, limit);
                    return null;
                }
                // a macro line ("#1=5", "IF [..] GOTO 5") has no words: it is no header, whatever comes first
                boolean header = blocks.isEmpty() && !b.malformed() && !b.words().isEmpty()
                        && b.words().get(0).letter() == gcnc.ir.Letter.O;
                if (header) {
                    start = b.words().get(0).span();
                    if (b.words().size() > 1) {
                        blocks.add(b.called(b.words().subList(1, b.words().size()), b.last(), 0));
                    }
                } else {
                    blocks.add(b);
                }
            }
        } catch (IOException e) {
            diags.report(Diagnostic.error(Code.E500_IO, Span.of(1, 1), gcnc.diag.Phrase.IO_CANNOT_READ.arg(),
                    gcnc.diag.Phrase.reason(e))
                    .in(Origin.file(shown)));
            return null;
        } finally {
            diags.placeIn(caller);
        }
        Program p = new Program(number, shown, blocks, start);
        held += blocks.size();
        programs.put(number, p);
        return p;
    }

    /** Bytes that are not UTF-8 become U+FFFD, which the parser reports (E003), as for the program itself. */
    private static Reader open(Path file) throws IOException {
        return new java.io.BufferedReader(new java.io.InputStreamReader(Files.newInputStream(file),
                StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPLACE)
                        .onUnmappableCharacter(CodingErrorAction.REPLACE)), 1 << 16);
    }

    /**
     * The file in {@code folder} that a call of {@code number} reads, as the check looks for it (the
     * first of {@link #names} that is a regular file); empty if none is. For a front end's "go to
     * definition" (the language server).
     */
    public static java.util.Optional<Path> fileFor(Path folder, long number) {
        for (String name : names(number)) {
            Path file = folder.resolve(name);
            if (Files.isRegularFile(file)) {
                return java.util.Optional.of(file);
            }
        }
        return java.util.Optional.empty();
    }

    /** The file names a call of {@code number} looks for, in order: O1000.nc, 1000.nc (P100: O0100.nc, 0100.nc, O100.nc, 100.nc). */
    static List<String> names(long number) {
        Set<String> names = new LinkedHashSet<>();
        String padded = Program.name(number);
        String plain = Long.toString(number);
        names.add("O" + padded + ".nc");
        names.add(padded + ".nc");
        names.add("O" + plain + ".nc");
        names.add(plain + ".nc");
        return List.copyOf(names);
    }

    /**
     * Every file beside the program that a call looked for, whether it was there or not: the run's
     * verdict can change when one of them is edited, added or removed (the Gradle plugin re-checks
     * the program then).
     */
    Set<Path> lookedFor() {
        return java.util.Collections.unmodifiableSet(lookedFor);
    }

    /** The note E138 for each program after the main program's end that no call reached. */
    void neverCalled() {
        for (Program p : programs.values()) {
            if (!called.contains(p.number()) && p.file() == null) {
                diags.report(MainFile.neverCalled(p));
            }
        }
    }
}
