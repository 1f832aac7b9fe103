package gcnc.diag;

/** How bad a finding is. Only ERROR stops output. */
public enum Severity {
    ERROR, WARNING, NOTE;

    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
