"""After a pause the server publishes the simulator's findings too: those of gcnc simulate."""
import pathlib
import shutil

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

from conftest import SERVER, gcnc_json, make_client, until

SAMPLES = pathlib.Path(__file__).resolve().parents[3] / "samples"


@pytest_lsp.fixture(config=ClientServerConfig(server_command=SERVER, client_factory=make_client))
async def client(lsp_client: LanguageClient, tmp_path_factory):
    root = tmp_path_factory.mktemp("sim")
    lsp_client.root = root
    await lsp_client.initialize_session(types.InitializeParams(
        capabilities=client_capabilities("neovim"), root_uri=root.as_uri(),
        initialization_options={"simulateAfterMs": 200, "checkDelayMs": 5, "explainFolder": str(root / ".explain")}))
    yield
    await lsp_client.shutdown_session()


@pytest.mark.asyncio(loop_scope="function")
async def test_the_simulators_findings_follow_the_checks(client: LanguageClient):
    path = client.root / "offsets.nc"
    shutil.copy(SAMPLES / "offsets.nc", path)
    text = path.read_text()
    client.text_document_did_open(types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(
        uri=path.as_uri(), language_id="gcode", version=1, text=text)))
    await until(client, lambda: client.publishes >= 1)
    first = [(d.code, d.range.start.line + 1) for d in client.diagnostics[path.as_uri()]]
    assert first == [(d["code"], d["line"]) for d in gcnc_json("check", path)] == []
    await until(client, lambda: client.publishes >= 2)
    second = [(d.code, d.range.start.line + 1, d.range.start.character + 1) for d in client.diagnostics[path.as_uri()]]
    assert second == [(d["code"], d["line"], d["column"]) for d in gcnc_json("simulate", path)] == [("E321", 12, 1)]
