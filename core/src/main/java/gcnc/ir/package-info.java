/**
 * The values the stages hand each other (records only): raw and checked blocks, words, motions
 * in machine counts, points and frames.
 */
package gcnc.ir;
