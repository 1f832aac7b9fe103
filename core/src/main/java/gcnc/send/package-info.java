/**
 * The sender of {@code gcnc run} (docs/run.md): after a clean compile, talks Galil's protocol to the
 * machine, downloads or streams the program, follows it and reports events to every front end.
 */
package gcnc.send;
