package gcnc.parse;

import gcnc.ir.RawBlock;
import java.io.IOException;

/**
 * The blocks the checker is given, in the order the control would execute them: the parser's
 * blocks as written ({@link BlockReader}), or a later stage that follows the program's flow
 * (subprogram calls, macro jumps) or expands a cycle. Null at the end.
 */
public interface BlockSource {
    RawBlock next() throws IOException;

    /** How many source lines were read (for the end-of-program checks). */
    int lines();
}
