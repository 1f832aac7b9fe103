/**
 * The resident checker ({@code gcnc daemon}): a warm JVM that runs the command line for the launcher's
 * client with the client's streams, environment and terminal; its state file and control.
 */
package gcnc.daemon;
