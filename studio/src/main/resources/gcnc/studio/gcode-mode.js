// G-code colouring for CodeMirror 6 (a StreamLanguage: no grammar generator in the build). It only colours;
// what is wrong is gcnc's checker's to say (POST /api/check), never this mode's.
import { StreamLanguage } from "@codemirror/language";

/** The rest of a "( ... )" comment, to its ")" or the end of the line (a comment never spans lines). */
function comment(stream) {
  if (stream.skipTo(")")) stream.next(); else stream.skipToEnd();
  return "comment";
}

export const gcode = StreamLanguage.define({
  name: "gcode",
  token(stream) {
    if (stream.eatSpace()) return null;
    if (stream.eat("(")) return comment(stream);
    if (stream.eat(";")) { stream.skipToEnd(); return "comment"; }
    if (stream.eat("%")) return "meta";
    if (stream.match(/^[Nn]\d+/)) return "meta";                       // sequence number
    if (stream.match(/^[Oo]\d+/)) return "def";                        // program number
    if (stream.match(/^[Gg]\d+(\.\d+)?/)) return "keyword";            // preparatory function
    if (stream.match(/^[Mm]\d+/)) return "atom";                       // miscellaneous function
    if (stream.match(/^[Tt]\d+/)) return "builtin";                    // tool
    if (stream.match(/^#\d+/)) return "variable";                      // macro variable
    if (stream.match(/^[A-Za-z]/)) return "variable-2";                // an address (X, Z, F ...)
    if (stream.match(/^[+-]?(\d+\.?\d*|\.\d+)/)) return "number";
    if (stream.match(/^[\[\]=*\/+-]/)) return "operator";
    stream.next();
    return null;
  },
  languageData: { commentTokens: { line: ";" } },
});
