package gcnc.galil;

/** Where a dialect writes its lines, in order. */
@FunctionalInterface
public interface LineSink {
    void accept(GalilLine line);
}
