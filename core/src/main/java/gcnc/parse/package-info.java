/**
 * Stage 1, parse: G-code text in, one {@link gcnc.ir.RawBlock} per line with words, with lexical and
 * syntax errors reported at their line and column ({@link gcnc.parse.BlockReader}).
 */
package gcnc.parse;
