package gcnc.output;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;

/**
 * What {@code compile} writes: the DMC program and, beside a regular file, its source map
 * ({@code part.dmc.map}); opened together, committed together (both replaced or neither) and
 * discarded together. Every front end that writes a DMC (the command line, the Gradle plugin)
 * writes it through this, so none of them can leave a half-written program or a map that belongs
 * to another DMC behind.
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

    private DmcOutputs(AtomicOutput dmc, AtomicOutput map) {
        this.dmc = dmc;
        this.map = map;
    }

    /** The DMC alone into a stream (standard output for {@code -o -}), once committed. */
    public static DmcOutputs toStream(OutputStream stream) throws Failed {
        try {
            return new DmcOutputs(AtomicOutput.toStream(stream), null);
        } catch (IOException e) {
            throw new Failed("<stdout>", e);
        }
    }

    /**
     * The DMC at {@code target} and, when {@code withMap} and the target is a regular file, its map
     * beside it; refuses the program itself as either file (E501) before anything is opened.
     * {@code input} is the program's file, or null when it comes from a stream.
     */
    public static DmcOutputs open(Path input, Path target, boolean withMap) throws Failed {
        Path mapPath = mapFile(target);
        AtomicOutput dmc;
        try {
            AtomicOutput.refuseInput(input, target);
            if (withMap) {
                AtomicOutput.refuseInput(input, mapPath);
            }
            dmc = new AtomicOutput(target);
        } catch (IOException e) {
            throw new Failed(target, e);
        }
        if (!withMap || !dmc.replacesFile()) {
            return new DmcOutputs(dmc, null);
        }
        try {
            return new DmcOutputs(dmc, new AtomicOutput(mapPath));
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

    /** Adds a line to the map; nothing when there is none. */
    public void mapLine(String text) {
        if (map != null) {
            map.line(text);
        }
    }

    /** Adds a map entry "{@code <dmc line> <source line>}"; nothing when there is no map. */
    public void mapEntry(int dmcLine, int sourceLine) {
        if (map != null) {
            map.line(dmcLine, sourceLine);
        }
    }

    /** Puts both in place, or neither: a failure of the second undoes the first. */
    public void commit() throws IOException {
        if (map != null) {
            AtomicOutput.commitAll(dmc, map);
        } else {
            dmc.commit();
        }
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
