package gcnc.lsp;

/**
 * Where the server says what went wrong: one line on standard error (never standard output, which
 * carries the protocol) and, once the client is connected, window/logMessage.
 */
interface Log {
    void error(String line);

    void info(String line);
}
