// The gcnc extension: starts `gcnc lsp` (the setting gcnc.command) for G-code buffers and hands it the
// machine, control and tables settings; everything else (diagnostics, hover, definition, symbols, quick
// fixes, the gcnc.explain command) is the server's (docs/editors.md).
import * as vscode from "vscode";
import { LanguageClient, LanguageClientOptions, ServerOptions, TransportKind } from "vscode-languageclient/node";

let client: LanguageClient | undefined;

function settings() {
  const c = vscode.workspace.getConfiguration("gcnc");
  return {
    machine: c.get<string>("machine", ""),
    control: c.get<string>("control", ""),
    tables: c.get<string>("tables", ""),
    simulateAfterMs: c.get<number>("simulateAfterMs", 500),
  };
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  const command = vscode.workspace.getConfiguration("gcnc").get<string[]>("command", ["gcnc", "lsp"]);
  const server: ServerOptions = { command: command[0], args: command.slice(1), transport: TransportKind.stdio };
  const options: LanguageClientOptions = {
    documentSelector: [{ scheme: "file", language: "gcode" }, { scheme: "untitled", language: "gcode" }],
    initializationOptions: settings(),
    synchronize: {
      // the server re-checks the open files when a folder's .gcnc, a profile or a table changes
      fileEvents: vscode.workspace.createFileSystemWatcher("**/{.gcnc,*.machine,*.csv}"),
    },
  };
  client = new LanguageClient("gcnc", "gcnc", server, options);
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration((e) => {
      if (e.affectsConfiguration("gcnc") && client) {
        client.sendNotification("workspace/didChangeConfiguration", { settings: { gcnc: settings() } });
      }
    })
  );
  await client.start();
}

export async function deactivate(): Promise<void> {
  if (client) {
    await client.stop();
  }
}
