/**
 * The interpreted path of {@code gcnc path} (docs/path.md): the checked blocks as rows in program
 * and machine coordinates, for the front ends.
 */
package gcnc.path;
