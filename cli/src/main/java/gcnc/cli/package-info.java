/**
 * The command line ({@code java -jar gcnc.jar}, docs/command-line.md): one picocli command per
 * subcommand, each over {@link gcnc.Session}.
 */
package gcnc.cli;
