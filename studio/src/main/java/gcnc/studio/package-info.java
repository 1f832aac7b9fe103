/**
 * gcnc studio, the local web editor (docs/studio.md): the workspace, analysis, drawing and run
 * screens served over HTTP, a front end over {@link gcnc.Session} like the command line.
 */
package gcnc.studio;
