/**
 * The library's entry point: {@link gcnc.Session} resolves tables, machine, control, dialect and blank once
 * for every front end, and {@link gcnc.Compiler} puts the stages together (docs/architecture.md).
 */
package gcnc;
