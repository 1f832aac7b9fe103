/**
 * Outputs that appear whole or not at all: the DMC and its source map committed as a pair (the
 * stream form's four files as one), temporary files removed on a signal, wear lines.
 */
package gcnc.output;
