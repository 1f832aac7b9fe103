package gcnc.output;

import gcnc.diag.Diagnostics;
import gcnc.dmc.DmcPrinter;
import gcnc.dmc.Form;
import gcnc.dmc.FormChoice;
import gcnc.dmc.Instruction;
import gcnc.dmc.LinePacker;
import gcnc.dmc.SourceMap;
import gcnc.machine.ControllerLimits;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * What {@code compile} writes, in either form (docs/galil.md, "Two forms"): the program form is
 * {@code part.dmc} (and its map); the stream form is {@code part.dmc}, the resident program, and
 * {@code part.stream}, the segment stream (each with its map; the resident's map names the stream
 * and its SHA-256, so a replay or a sender can tell a stream of another compile). All the files of
 * one compile are put in place together or none; a program-form compile removes a stream an earlier
 * compile left beside the same DMC, so a sender cannot pair them.
 */
public final class FormOutputs implements AutoCloseable {
    private final DmcOutputs dmc;
    /** The stream's files; null when the output is standard output (the program form only). */
    private final DmcOutputs stream;
    private final Path streamPath;
    private final SourceMap dmcMap;
    private final SourceMap streamMap;
    private FormChoice choice;
    private Form form = Form.PROGRAM;

    private FormOutputs(DmcOutputs dmc, DmcOutputs stream, Path streamPath) {
        this.dmc = dmc;
        this.stream = stream;
        this.streamPath = streamPath;
        this.dmcMap = SourceMap.toEntries(dmc::mapEntry).withStops(dmc::mapStop);
        this.streamMap = stream == null ? null : SourceMap.toEntries(stream::mapEntry).withStops(stream::mapStop);
    }

    /** The program alone into a stream (standard output for {@code -o -}): the program form only. */
    public static FormOutputs toStream(OutputStream out) throws DmcOutputs.Failed {
        return new FormOutputs(DmcOutputs.toStream(out), null, null);
    }

    /**
     * The DMC at {@code target}, and the stream beside it ({@link #streamFile}), each with its map
     * when {@code withMap}; refuses the program itself as any of them (E501) before anything is
     * opened, and a symbolic link at any name gcnc chose (E510): the maps, the stream, and the DMC
     * when {@code name} is {@link AtomicOutput.Name#DERIVED}. The stream is never named by the user.
     */
    public static FormOutputs open(Path input, Path target, boolean withMap, AtomicOutput.Name name) throws DmcOutputs.Failed {
        Path streamPath = streamFile(target);
        DmcOutputs dmc = DmcOutputs.open(input, target, withMap, name);
        try {
            return new FormOutputs(dmc, DmcOutputs.open(input, streamPath, withMap, AtomicOutput.Name.DERIVED), streamPath);
        } catch (DmcOutputs.Failed e) {
            dmc.close();
            throw e;
        }
    }

    /** The stream's name beside a DMC: {@code part.dmc} has {@code part.stream}, {@code part.out} {@code part.out.stream}. */
    public static Path streamFile(Path target) {
        Path name = target.getFileName();
        String n = name == null ? "" : name.toString();
        return target.resolveSibling((n.endsWith(".dmc") ? n.substring(0, n.length() - 4) : n) + ".stream");
    }

    /** The maps' heads: the G-code file's name and SHA-256 ({@link DmcOutputs#mapSource}). */
    public void mapSource(String name, Path program) {
        if (!dmc.hasMap() && (stream == null || !stream.hasMap())) {
            return;
        }
        String hash = DmcOutputs.programHash(program); // once for both maps (a read of the whole program)
        dmc.mapSource(name, hash);
        if (stream != null) {
            stream.mapSource(name, hash);
        }
    }

    /**
     * Where the compiled instructions go, in the program form's order: into the form asked for, or
     * the one that fits {@code limits}' program memory (none asked). Standard output takes the program
     * form only. The DMC (the program, or the resident program) is packed into lines of the model's
     * width ({@link LinePacker}); the stream is one command a line, as the host sends it.
     */
    public Consumer<Instruction> sink(Optional<Form> asked, ControllerLimits limits) {
        Consumer<LinePacker.Line> toDmc = dmcMap.wrapLines(l -> dmc.dmcLine(l.text()));
        if (stream == null) {
            choice = new FormChoice(Optional.of(Form.PROGRAM), limits, toDmc, i -> { });
        } else {
            choice = new FormChoice(asked, limits, toDmc, streamMap.wrap(i -> stream.dmcLine(DmcPrinter.print(i.command()))));
        }
        return choice;
    }

    /** The instructions as they come, one a line, into the DMC alone: no form (the thesis's format). */
    public Consumer<Instruction> programSink() {
        return dmcMap.wrap(i -> dmc.dmcLine(DmcPrinter.print(i.command())));
    }

    /**
     * After a clean compile: the form decided, the resident program written (stream form), and what
     * does not fit reported to {@code diagnostics} (E238, E239, E243).
     */
    public Form finish(Diagnostics diagnostics) {
        if (choice != null) {
            form = choice.finish(diagnostics);
        }
        return form;
    }

    /** The form written. */
    public Form form() {
        return form;
    }

    /** Lines written to the DMC (the program, or the resident program). */
    public int dmcLines() {
        return dmcMap.lines();
    }

    /** Lines written to the stream (0 in the program form). */
    public int streamLines() {
        return streamMap == null ? 0 : streamMap.lines();
    }

    /** The stream's file, when there is one. */
    public Optional<Path> streamPath() {
        return Optional.ofNullable(streamPath);
    }

    /**
     * Puts the files of the form written in place, all or none. The program form removes a stream
     * (and its map) an earlier compile left beside the DMC.
     */
    public void commit() throws IOException {
        if (form == Form.PROGRAM) {
            dmc.commit();
            if (stream != null) {
                stream.close();
                for (Path p : List.of(streamPath, DmcOutputs.mapFile(streamPath))) {
                    if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS) || Files.isSymbolicLink(p)) {
                        Files.delete(p);
                    }
                }
            }
            return;
        }
        if (dmc.hasMap()) {
            dmc.mapNote(SourceMap.STREAM + streamPath.getFileName());
            if (stream.hasMap()) {
                dmc.mapNote(SourceMap.STREAM_HASH + stream.dmcSha256());
            }
        }
        List<AtomicOutput> all = new ArrayList<>(dmc.sealed());
        all.addAll(stream.sealed());
        AtomicOutput.commitAll(all.toArray(AtomicOutput[]::new));
        dmc.dropStale();
        stream.dropStale();
    }

    @Override
    public void close() {
        dmc.close();
        if (stream != null) {
            stream.close();
        }
    }
}
