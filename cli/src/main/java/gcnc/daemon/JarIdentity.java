package gcnc.daemon;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * The jar a server runs, as it was when the server started: its real path, size and modification
 * time. A client whose launcher runs another jar, or this one replaced since (a new build, a new
 * install), runs cold: the server's classes would not be the jar's.
 *
 * @param path     the jar's real path
 * @param size     its size in bytes
 * @param modified its modification time, in milliseconds
 */
record JarIdentity(String path, long size, long modified) {
    static JarIdentity ofRunningJar() throws IOException {
        try {
            Path p = Path.of(DaemonServer.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            return of(p);
        } catch (URISyntaxException e) {
            throw new IOException(e);
        }
    }

    static JarIdentity of(Path jar) throws IOException {
        Path real = jar.toRealPath();
        BasicFileAttributes a = Files.readAttributes(real, BasicFileAttributes.class);
        return new JarIdentity(real.toString(), a.size(), a.lastModifiedTime().toMillis());
    }

    /** The jar at the path is no longer the one loaded (replaced, rebuilt or gone). */
    boolean changed() {
        try {
            JarIdentity now = of(Path.of(path));
            return now.size != size || now.modified != modified;
        } catch (IOException e) {
            return true;
        }
    }

    /** Whether a client's launcher, running {@code clientJar}, would run this very jar. */
    boolean serves(String clientJar) {
        try {
            return Path.of(clientJar).toRealPath().toString().equals(path) && !changed();
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }
}
