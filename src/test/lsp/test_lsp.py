"""The language server through a real LSP client (pytest-lsp, pygls): open, edit, diagnostics, hover,
definition, references, symbols, code actions, folder settings; its findings equal gcnc check's."""
import asyncio
import pathlib

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

from conftest import SERVER, gcnc_json, make_client, until

# E107 at line 6 (X50), E120 at line 3 (TO303), E107 at 7 (Z-10), E038 at 7, E004 at 8
PROGRAM = """O1000 (FACE AND TURN)
G21 G40 G99
TO303
G50 S2000
G96 S200 M03
G00 X50 Z2.
G01 X40. Z-10 F0.2
G01 Y5.
M30
"""

FLOW = """O0001
G21 G40 G99
G50 S2000
T0101 (OD ROUGH)
G97 S500 M03
M98 P1000
G00 X52. Z2.
G71 U1. R0.5
G71 P100 Q200 U0.2 W0.1 F0.25
N100 G00 X20.
G01 Z-10.
N200 X52.
G70 P100 Q200
M97 P300
M30
N300 G00 X60.
M99
"""


def initialize_params(root: pathlib.Path, **options):
    return types.InitializeParams(
        capabilities=client_capabilities("visual-studio-code"),
        root_uri=root.as_uri(),
        workspace_folders=[types.WorkspaceFolder(uri=root.as_uri(), name="parts")],
        initialization_options={"simulateAfterMs": options.get("simulate", -1), "checkDelayMs": 5,
                                "explainFolder": str(root / ".explain"), **options.get("extra", {})},
    )


@pytest_lsp.fixture(config=ClientServerConfig(server_command=SERVER, client_factory=make_client))
async def client(lsp_client: LanguageClient, tmp_path_factory):
    root = tmp_path_factory.mktemp("parts")
    lsp_client.root = root
    await lsp_client.initialize_session(initialize_params(root))
    yield
    await lsp_client.shutdown_session()


async def published(client: LanguageClient, uri: str, version: int):
    """Waits for the diagnostics of `version` of `uri`."""
    await until(client, lambda: client.last_version.get(uri) == version)
    return client.diagnostics[uri]


def open_file(client: LanguageClient, path: pathlib.Path, text: str, version: int = 1):
    path.write_text(text)
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        text_document=types.TextDocumentItem(uri=path.as_uri(), language_id="gcode", version=version, text=text)))


def keyed(diags):
    """(code, line, column, endColumn) of the server's diagnostics, 1-based as gcnc prints them."""
    return [(d.code, d.range.start.line + 1, d.range.start.character + 1, d.range.end.character + 1) for d in diags]


def keyed_json(found, text):
    lines = text.splitlines()
    out = []
    for d in found:
        end = d.get("endColumn")
        if end is None:  # no end known: the server covers the word (to the next blank)
            line = lines[d["line"] - 1]
            e = d["column"] - 1
            while e < len(line) and not line[e].isspace():
                e += 1
            end = max(e, d["column"]) + 1
        out.append((d["code"], d["line"], d["column"], end))
    return out


@pytest.mark.asyncio(loop_scope="function")
async def test_diagnostics_on_open_and_edit_equal_gcnc_check(client: LanguageClient):
    path = client.root / "part.nc"
    open_file(client, path, PROGRAM)
    diags = await published(client, path.as_uri(), 1)
    assert keyed(diags) == keyed_json(gcnc_json("check", path), PROGRAM)
    assert {d.code for d in diags} == {"E107", "E120", "E038", "E004"}
    e107 = next(d for d in diags if d.code == "E107")
    assert e107.source == "gcnc" and e107.code_description.href.endswith("E107.txt")
    assert pathlib.Path(e107.code_description.href[len("file://"):]).read_text().startswith("E107 (warning)")
    # an edit: the decimal point written, the Y removed
    edited = PROGRAM.replace("X50 Z2.", "X50. Z2.").replace("G01 Y5.\n", "")
    client.text_document_did_change(types.DidChangeTextDocumentParams(
        text_document=types.VersionedTextDocumentIdentifier(uri=path.as_uri(), version=2),
        content_changes=[types.TextDocumentContentChangeWholeDocument(text=edited)]))
    diags = await published(client, path.as_uri(), 2)
    path.write_text(edited)
    assert keyed(diags) == keyed_json(gcnc_json("check", path), edited)
    assert [d.code for d in diags].count("E107") == 1 and "E004" not in [d.code for d in diags]


@pytest.mark.asyncio(loop_scope="function")
async def test_hover_shows_the_function_and_the_modal_state(client: LanguageClient):
    path = client.root / "hover.nc"
    open_file(client, path, PROGRAM)
    await published(client, path.as_uri(), 1)
    hover = await client.text_document_hover_async(types.HoverParams(
        text_document=types.TextDocumentIdentifier(uri=path.as_uri()), position=types.Position(line=4, character=1)))
    text = hover.contents.value
    assert text.startswith("**G96** ") and "control thesis-2004" in text, text
    assert "After this block" in text and "spindle G96 S200" in text and "clamp 2000. rpm" in text, text
    assert hover.range.start == types.Position(line=4, character=0)


@pytest.mark.asyncio(loop_scope="function")
async def test_definition_references_and_symbols(client: LanguageClient):
    folder = client.root / "flow"  # a control with calls: the Haas (M97, M98, M99)
    folder.mkdir()
    (folder / ".gcnc").write_text("machine = haas\n")
    (folder / "O1000.nc").write_text("O1000\nG00 X40. Z1.\nM99\n")
    path = folder / "flow.nc"
    open_file(client, path, FLOW)
    await published(client, path.as_uri(), 1)
    doc = types.TextDocumentIdentifier(uri=path.as_uri())

    async def definition(line, character):
        return await client.text_document_definition_async(types.DefinitionParams(
            text_document=doc, position=types.Position(line=line, character=character)))

    call = await definition(5, 5)  # M98 P1000: the file O1000.nc beside it
    assert [loc.uri for loc in call] == [(folder / "O1000.nc").as_uri()]
    q = await definition(8, 11)  # G71 P100 Q200: Q200 is N200 at line 12
    assert [(loc.uri, loc.range.start.line) for loc in q] == [(path.as_uri(), 11)]
    local = await definition(13, 5)  # M97 P300: N300 at line 16
    assert [loc.range.start.line for loc in local] == [15]
    refs = await client.text_document_references_async(types.ReferenceParams(
        text_document=doc, position=types.Position(line=9, character=1),
        context=types.ReferenceContext(include_declaration=True)))
    # N100 itself, the P100 of the G71 and of the G70
    assert sorted((r.range.start.line, r.range.start.character) for r in refs) == [(8, 4), (9, 0), (12, 4)]
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=doc))
    assert [s.name for s in symbols] == ["O0001"]
    operation = symbols[0].children[0]
    assert (operation.name, operation.detail) == ("T0101", "OD ROUGH")
    assert [c.name for c in operation.children] == ["G71", "G71", "G70"]


@pytest.mark.asyncio(loop_scope="function")
async def test_code_actions_fix_and_explain(client: LanguageClient):
    path = client.root / "fix.nc"
    open_file(client, path, PROGRAM)
    diags = await published(client, path.as_uri(), 1)
    wanted = [d for d in diags if d.code in ("E107", "E120")]
    actions = await client.text_document_code_action_async(types.CodeActionParams(
        text_document=types.TextDocumentIdentifier(uri=path.as_uri()), range=wanted[0].range,
        context=types.CodeActionContext(diagnostics=wanted)))
    explains = [a for a in actions if isinstance(a, types.Command)]
    assert [(a.title, a.command, a.arguments) for a in explains] == [
        ("Explain E120", "gcnc.explain", ("E120",)), ("Explain E107", "gcnc.explain", ("E107",))]
    edits = {a.title: a.edit.changes[path.as_uri()][0] for a in actions if isinstance(a, types.CodeAction)}
    assert all(a.kind == types.CodeActionKind.QuickFix for a in actions if isinstance(a, types.CodeAction))
    assert edits["Write T0303 (E120)"].new_text == "T0303"
    assert edits["Write T0303 (E120)"].range == types.Range(start=types.Position(line=2, character=0),
                                                            end=types.Position(line=2, character=5))
    assert edits["Write X50. (E107)"].new_text == "X50."
    assert edits["Write Z-10. (E107)"].new_text == "Z-10."
    explained = await client.workspace_execute_command_async(types.ExecuteCommandParams(
        command="gcnc.explain", arguments=["E107"]))
    assert explained.startswith("E107 (warning)") and "Fix:" in explained
    assert client.shown_documents[-1].uri.endswith("/E107.txt")


@pytest.mark.asyncio(loop_scope="function")
async def test_a_gcnc_file_sets_the_machine_and_a_change_to_it_checks_again(client: LanguageClient):
    folder = client.root / "haas"
    folder.mkdir()
    settings = folder / ".gcnc"
    settings.write_text("# the shop's lathe\nmachine = haas\n")
    path = folder / "part.nc"
    open_file(client, path, PROGRAM)
    diags = await published(client, path.as_uri(), 1)
    assert keyed(diags) == keyed_json(gcnc_json("check", path, "--machine", "haas"), PROGRAM)
    generic = keyed_json(gcnc_json("check", path), PROGRAM)
    assert keyed(diags) != generic  # the machine matters to this program
    settings.write_text("machine = generic\n")
    client.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[
        types.FileEvent(uri=settings.as_uri(), type=types.FileChangeType.Changed)]))
    await until(client, lambda: keyed(client.diagnostics[path.as_uri()]) == generic)
    settings.write_text("machin = haas\n")  # a typo: shown on the .gcnc file itself
    client.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(changes=[
        types.FileEvent(uri=settings.as_uri(), type=types.FileChangeType.Changed)]))
    await until(client, lambda: client.diagnostics.get(settings.as_uri()))
    assert "unknown key 'machin'" in client.diagnostics[settings.as_uri()][0].message
