/**
 * {@code gcnc lsp}, the language server for the programmer's editor (docs/editors.md, Eclipse LSP4J):
 * findings as diagnostics, hover, outline, code actions, over {@link gcnc.Session}.
 */
package gcnc.lsp;
