package gcnc.send;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonParseException;
import gcnc.machine.ProbeRow;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What {@code gcnc controller probe} found on one controller, written as a JSON file (docs/run.md,
 * "The probe report"): the unit's revision, the link it was probed over, the facts it read (memory,
 * limits, smoothing), and one result per {@link ProbeRow}: confirmed, contradicted or not checked,
 * with what the reference gives and what the unit answered. {@code gcnc run --probe-report FILE} reads
 * it back and refuses a unit that contradicts a row the run relies on (E832).
 */
public record ProbeReport(String revision, String link, Map<String, String> facts, List<Result> rows) {
    /** confirmed, contradicted, not-checked: the JSON spellings. */
    public enum Status {
        CONFIRMED, CONTRADICTED, NOT_CHECKED;

        /** The constant's name in lower case with hyphens ({@code not-checked}). */
        public String spelling() {
            return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
        }

        static Status of(String s) {
            for (Status v : values()) {
                if (v.spelling().equals(s)) {
                    return v;
                }
            }
            throw new IllegalArgumentException("'" + s + "' is not confirmed, contradicted or not-checked");
        }
    }

    /** One row: its id, what the reference gives, what the unit answered, the outcome. */
    public record Result(ProbeRow row, Status status, String expected, String observed) {
    }

    public ProbeReport {
        facts = Map.copyOf(facts);
        rows = List.copyOf(rows);
    }

    /** The rows the unit contradicted. */
    public List<ProbeRow> contradicted() {
        List<ProbeRow> out = new ArrayList<>();
        for (Result r : rows) {
            if (r.status() == Status.CONTRADICTED) {
                out.add(r.row());
            }
        }
        return out;
    }

    /** The JSON form: rows keyed by id, in ProbeRow's order, with the reference's words for the reader. */
    private record Json(String revision, String link, Map<String, String> facts, List<JsonRow> rows) {
    }

    private record JsonRow(String id, String status, String expected, String observed, String reference) {
    }

    public void write(Path file) throws IOException {
        List<JsonRow> out = new ArrayList<>();
        for (Result r : rows) {
            out.add(new JsonRow(r.row().id(), r.status().spelling(), r.expected(), r.observed(), r.row().reference()));
        }
        Gson g = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();
        Files.writeString(file, g.toJson(new Json(revision, link, new LinkedHashMap<>(facts), out)) + "\n",
                StandardCharsets.UTF_8);
    }

    /** Reads a report; IOException with the reason for a file that is not one (a row id gcnc does not know, bad JSON). */
    public static ProbeReport read(Path file) throws IOException {
        Json j;
        try {
            j = new Gson().fromJson(Files.readString(file, StandardCharsets.UTF_8), Json.class);
        } catch (JsonParseException e) {
            throw new IOException("not a probe report (" + e.getMessage() + ")");
        }
        if (j == null || j.rows() == null) {
            throw new IOException("not a probe report (no rows)");
        }
        List<Result> rows = new ArrayList<>();
        for (JsonRow r : j.rows()) {
            ProbeRow row = ProbeRow.byId(String.valueOf(r.id()))
                    .orElseThrow(() -> new IOException("row '" + r.id() + "' is no probe row gcnc knows"));
            try {
                rows.add(new Result(row, Status.of(String.valueOf(r.status())), r.expected(), r.observed()));
            } catch (IllegalArgumentException e) {
                throw new IOException("row " + r.id() + ": " + e.getMessage());
            }
        }
        return new ProbeReport(String.valueOf(j.revision()), String.valueOf(j.link()),
                j.facts() == null ? Map.of() : j.facts(), rows);
    }
}
