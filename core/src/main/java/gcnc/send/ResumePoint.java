package gcnc.send;

/**
 * Where {@code --resume-at} continues: G-code line {@code line} and, within a block that makes
 * several motions (a canned cycle, G28), its {@code motion}-th one (1-based; 0 = the block's start).
 * Written {@code N} or {@code N:K}.
 */
public record ResumePoint(int line, int motion) {
    public static ResumePoint parse(String text) {
        String[] f = text.strip().split(":", -1);
        try {
            int line = Integer.parseInt(f[0]);
            int motion = f.length > 1 ? Integer.parseInt(f[1]) : 0;
            if (f.length > 2 || line < 1 || motion < 0) {
                throw new IllegalArgumentException(text);
            }
            return new ResumePoint(line, motion);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--resume-at takes a G-code line, N or N:K (K: the block's K-th motion): " + text);
        }
    }

    @Override
    public String toString() {
        return motion == 0 ? Integer.toString(line) : line + ":" + motion;
    }
}
