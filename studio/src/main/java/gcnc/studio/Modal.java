package gcnc.studio;

import com.google.gson.JsonObject;
import gcnc.ModalStates;
import gcnc.ModalStates.Snapshot;
import gcnc.Session;
import gcnc.machine.FunctionText;
import gcnc.machine.MachineProfile;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;

/**
 * The hover: what a G or M word does on this control (its row of g_codes.csv or m_codes.csv, in
 * the page's language) and the modal state the control is in after the block of that line
 * (units, feed mode and feed, G96 surface speed and the rpm it gives at the block's X, work
 * offset, tool and offset, where the tool is), as {@link ModalStates} computes it for every front
 * end's hover (the language server's too). The last text's states are kept, so hovering along one
 * version of the program checks it once; those of the page's own check are taken as they are, so a
 * text the page checked is not checked again for its hover.
 */
final class Modal {
    private final Session session;
    private final ErrorMessages.Lang lang;
    private String lastKey;
    private Map<Integer, Snapshot> last = Map.of();

    Modal(Session session, ErrorMessages.Lang lang) {
        this.session = session;
        this.lang = lang;
    }

    /** {@code POST /api/hover}: the function of {@code word} (if a G or M) and the state after {@code line}'s block. */
    JsonObject hover(String name, String text, int line, String word, Optional<Path> folder) throws IOException {
        JsonObject o = new JsonObject();
        o.addProperty("line", line);
        if (word != null) {
            o.addProperty("word", word);
            JsonObject f = function(word);
            if (f != null) {
                o.add("function", f);
            }
        }
        Snapshot s = states(name, text, folder).get(line);
        if (s != null) {
            o.add("state", state(s));
        }
        return o;
    }

    /** The function a G or M word names on this control ({@link FunctionText}), or null (another letter). */
    JsonObject function(String word) {
        Optional<FunctionText> found = FunctionText.of(session.profile().control(), word);
        if (found.isEmpty()) {
            return null;
        }
        FunctionText f = found.get();
        JsonObject o = new JsonObject();
        o.addProperty("code", f.name());
        if (!f.known()) {
            o.addProperty("unknown", true);
        } else {
            o.addProperty("text", lang == ErrorMessages.Lang.ES ? f.spanish() : f.english());
            o.addProperty("group", f.group());
            if (f.letter() == 'G') {
                o.addProperty("modal", f.modal());
            } else {
                o.addProperty("moment", f.moment());
            }
        }
        o.addProperty("control", f.control());
        return o;
    }

    /** The states of a text, the last one's kept. */
    synchronized Map<Integer, Snapshot> states(String name, String text, Optional<Path> folder) throws IOException {
        String key = key(name, text, folder);
        if (!key.equals(lastKey)) {
            last = ModalStates.of(session.withPrograms(folder), new StringReader(text));
            lastKey = key;
        }
        return last;
    }

    /**
     * The states a check of this text saw ({@code POST /api/check}, with {@link ModalStates#view} as its
     * observer): kept as the last text's, so the hover that follows the check does not check it again.
     */
    synchronized void seen(String name, String text, Optional<Path> folder, Map<Integer, Snapshot> states) {
        last = states;
        lastKey = key(name, text, folder);
    }

    private static String key(String name, String text, Optional<Path> folder) {
        return name + '\u0000' + folder.map(Path::toString).orElse("") + '\u0000' + text;
    }

    /** The state as the page shows it ({@link ModalStates#summary}): G names as this control writes them, offsets in machine mm. */
    private JsonObject state(Snapshot s) {
        MachineProfile p = session.profile();
        ModalStates.Summary m = ModalStates.summary(s, p);
        JsonObject o = new JsonObject();
        o.addProperty("accepted", m.accepted());
        o.addProperty("runs", m.runs());
        o.addProperty("units", m.units());
        o.addProperty("unitsG", m.unitsG());
        o.addProperty("motion", m.motion());
        o.addProperty("incremental", m.incremental());
        o.addProperty("feedPerRev", m.feedPerRev());
        o.addProperty("feedG", m.feedG());
        o.addProperty("feed", m.feed());
        o.addProperty("css", m.css());
        o.addProperty("spindleG", m.spindleG());
        o.addProperty("surfaceSpeed", m.surfaceSpeed());
        o.addProperty("rpm", m.rpm());
        o.addProperty("rpmClamp", m.rpmClamp());
        m.blockRpm().ifPresent(r -> o.addProperty("blockRpm", r));
        o.addProperty("workOffset", m.workOffset());
        m.workOffsetMm().ifPresent(w -> o.add("workOffsetMm", mm(w)));
        o.addProperty("tool", m.tool());
        o.addProperty("toolOffset", m.toolOffset());
        m.toolOffsetMm().ifPresent(t -> o.add("toolOffsetMm", mm(t)));
        o.addProperty("nose", m.nose());
        m.at().ifPresent(a -> {
            JsonObject at = new JsonObject();
            at.addProperty("x", a.x());
            at.addProperty("z", a.z());
            at.addProperty("diameter", a.diameter());
            o.add("at", at);
        });
        return o;
    }

    private static JsonObject mm(ModalStates.Mm v) {
        JsonObject o = new JsonObject();
        o.addProperty("x", v.x());
        o.addProperty("z", v.z());
        return o;
    }
}
