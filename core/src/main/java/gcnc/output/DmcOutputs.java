package gcnc.output;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;

/**
 * What {@code compile} writes: the DMC program and, beside a regular file, its source map
 * ({@code part.dmc.map}); opened together, committed together (both replaced or neither) and
 * discarded together. Every front end that writes a DMC (the command line, the Gradle plugin)
 * writes it through this, so none of them can leave a half-written program or a map that belongs
 * to another DMC behind:
 * <ul>
 *   <li>the map's last line records the SHA-256 of the DMC it was written with
 *       ({@code # dmc sha256 <hex>}), so a replay can tell a map of another DMC (E331);</li>
 *   <li>a compile that writes no map (--source-map puts the lines in the DMC) removes the map an
 *       earlier compile left beside the same DMC, in the same commit: it is moved aside before the
 *       DMC is put in place and back if that fails;</li>
 *   <li>the map is a file the user never named: when its name is a symbolic link, gcnc does not
 *       write through it (E510), since whoever planted the link would choose the file a compile
 *       replaces ({@link AtomicOutput.Name#DERIVED}). The DMC itself is written through a link
 *       only when the user named it (-o).</li>
 * </ul>
 */
public final class DmcOutputs implements AutoCloseable {
    /** An output that could not be opened, and which one. */
    public static final class Failed extends Exception {
        private final String path;
        private final IOException problem;

        Failed(Object path, IOException cause) {
            super(cause);
            this.path = path.toString();
            this.problem = cause;
        }

        /** The file that could not be opened, as it was named. */
        public String path() {
            return path;
        }

        /** Why ({@link AtomicOutput.Refused} for the program itself or a directory). */
        public IOException problem() {
            return problem;
        }
    }

    private final AtomicOutput dmc;
    private final AtomicOutput map;
    /** A map an earlier compile left beside the DMC, removed when this one is committed without a map; or null. */
    private final Path stale;

    private DmcOutputs(AtomicOutput dmc, AtomicOutput map, Path stale) {
        this.dmc = dmc;
        this.map = map;
        this.stale = stale;
    }

    /** The DMC alone into a stream (standard output for {@code -o -}), once committed. */
    public static DmcOutputs toStream(OutputStream stream) throws Failed {
        try {
            return new DmcOutputs(AtomicOutput.toStream(stream), null, null);
        } catch (IOException e) {
            throw new Failed("<stdout>", e);
        }
    }

    /**
     * The DMC at {@code target} and, when {@code withMap} and the target is a regular file, its map
     * beside it; refuses the program itself as either file (E501) before anything is opened, and a
     * link at the map's name, or at the DMC's when gcnc chose it ({@code name}), E510.
     * {@code input} is the program's file, or null when it comes from a stream.
     */
    public static DmcOutputs open(Path input, Path target, boolean withMap, AtomicOutput.Name name) throws Failed {
        Path mapPath = mapFile(target);
        AtomicOutput dmc;
        try {
            AtomicOutput.refuseInput(input, target);
            if (withMap) {
                AtomicOutput.refuseInput(input, mapPath);
            }
            dmc = AtomicOutput.open(target, name);
        } catch (IOException e) {
            throw new Failed(target, e);
        }
        boolean beside = dmc.replacesFile();
        if (!withMap || !beside) {
            // a map left by an earlier compile of this DMC would be believed by a replay: it goes
            Path stale = beside && Files.exists(mapPath, LinkOption.NOFOLLOW_LINKS) ? mapPath : null;
            return new DmcOutputs(dmc, null, stale);
        }
        try {
            AtomicOutput map = AtomicOutput.open(mapPath, AtomicOutput.Name.DERIVED);
            dmc.hashed(); // the map's last line records it
            return new DmcOutputs(dmc, map, null);
        } catch (IOException e) {
            discard(dmc);
            throw new Failed(mapPath, e);
        }
    }

    /** The map's name for a DMC: {@code part.dmc} has {@code part.dmc.map}. */
    public static Path mapFile(Path target) {
        Path name = target.getFileName();
        return target.resolveSibling((name == null ? "" : name.toString()) + ".map");
    }

    /** The DMC's name for a program: {@code part.nc} compiles to {@code part.dmc} beside it. */
    public static Path defaultOutput(Path program) {
        String name = program.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return program.resolveSibling((dot > 0 ? name.substring(0, dot) : name) + ".dmc");
    }

    /** Adds a line to the DMC. */
    public void dmcLine(String text) {
        dmc.line(text);
    }

    /** Whether a map is written (not for a stream, a device or when it was not asked for). */
    public boolean hasMap() {
        return map != null;
    }

    /**
     * The map's head: the G-code file's name ({@code # source <name>}) and, when it is a regular
     * file that can be read, its SHA-256 ({@code # source sha256 <hex>}); nothing when there is no map.
     */
    public void mapSource(String name, Path program) {
        if (map != null) {
            mapSource(name, programHash(program));
        }
    }

    /**
     * The map's head with the program's SHA-256 already worked out ({@link #programHash}; null: none),
     * so that the maps of one compile (the stream form's two) hash the program once.
     */
    void mapSource(String name, String programHash) {
        if (map == null) {
            return;
        }
        map.line(gcnc.dmc.SourceMap.sourceLine(name));
        if (programHash != null) {
            map.line(gcnc.dmc.SourceMap.SOURCE_HASH + programHash);
        }
    }

    /** The SHA-256 of the program for the map's head, or null when it has none (not a regular file, unreadable). */
    static String programHash(Path program) {
        // a regular file only: a named pipe would be drained here and the compile would wait for it forever
        if (program != null && Files.isRegularFile(program)) {
            try {
                return sha256(program);
            } catch (IOException e) {
                // the program was read a moment ago; without its hash the map still names it
            }
        }
        return null;
    }

    /**
     * Adds a map entry "{@code <dmc line> <source line>}" ({@code <dmc line>.<k>} when the run starts
     * at the k-th command of a packed line), with the file after them when the line is in another
     * file than the program's; nothing when there is no map.
     */
    public void mapEntry(int dmcLine, int statement, int sourceLine, String file) {
        if (map == null) {
            return;
        }
        if (file == null) {
            map.line(dmcLine, statement, sourceLine);
        } else {
            map.line(dmcLine + (statement == 0 ? "" : "." + statement) + " " + sourceLine + " " + file);
        }
    }

    /** Adds a stop line ({@code # stop <dmc line> <reason>}); nothing when there is no map. */
    public void mapStop(int dmcLine, gcnc.plan.Stop why) {
        if (map != null) {
            map.line(gcnc.dmc.SourceMap.stopLine(dmcLine, why));
        }
    }

    /** Adds a line to the map before its last; nothing when there is no map. */
    void mapNote(String line) {
        if (map != null) {
            map.line(line);
        }
    }

    /** The DMC's SHA-256, lowercase hex; ends the DMC (no line may follow). */
    String dmcSha256() throws IOException {
        if (sha256 == null) {
            sha256 = dmc.sha256();
        }
        return sha256;
    }

    /** The DMC's SHA-256 once asked for (it can be computed once). */
    private String sha256;

    /**
     * The files to put in place with others ({@link AtomicOutput#commitAll}): the DMC and its map,
     * the map's last line written; a stale map beside the DMC is {@link #dropStale dropped} after.
     */
    List<AtomicOutput> sealed() throws IOException {
        if (map == null) {
            return List.of(dmc);
        }
        map.line(gcnc.dmc.SourceMap.DMC_HASH + dmcSha256());
        return List.of(dmc, map);
    }

    /** Removes the map an earlier compile left beside the DMC (after a commit by {@link #sealed}). */
    void dropStale() throws IOException {
        if (stale != null) {
            Files.deleteIfExists(stale);
        }
    }

    /**
     * Puts both in place, or neither: a failure of the second undoes the first. The map ends with
     * the DMC's SHA-256; without a map, a stale one beside the DMC is removed with the commit.
     */
    public void commit() throws IOException {
        if (map != null) {
            map.line(gcnc.dmc.SourceMap.DMC_HASH + dmc.sha256());
            AtomicOutput.commitAll(dmc, map);
        } else if (stale != null) {
            commitRemovingStale();
        } else {
            dmc.commit();
        }
    }

    /**
     * The stale map moved aside (the link itself, if it is one: never what it points to), the DMC
     * put in place, then the aside copy deleted; if the DMC cannot be put in place the map comes back.
     */
    private void commitRemovingStale() throws IOException {
        Path aside = TempFiles.create(stale.toAbsolutePath().getParent(), "." + stale.getFileName(), ".stale");
        Files.move(stale, aside, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        try {
            dmc.commit();
        } catch (IOException | RuntimeException e) {
            try {
                Files.move(aside, stale, StandardCopyOption.ATOMIC_MOVE);
                TempFiles.forget(aside);
            } catch (IOException | RuntimeException u) {
                e.addSuppressed(u);
            }
            throw e;
        }
        TempFiles.delete(aside);
    }

    /** The SHA-256 of a file (a G-code program, for its map's {@code # source sha256} line), lowercase hex. */
    public static String sha256(Path file) throws IOException {
        return AtomicOutput.sha256(file);
    }

    /** Removes what was not committed; a temporary file that cannot be removed is no reason to fail the run. */
    @Override
    public void close() {
        discard(map);
        discard(dmc);
    }

    private static void discard(AtomicOutput o) {
        if (o == null) {
            return;
        }
        try {
            o.close();
        } catch (IOException e) {
            // The shutdown hook (TempFiles) tries once more at exit.
        }
    }
}
