"""pytest-lsp drives `gcnc lsp` (the jar in GCNC_JAR) as an editor would; LspClientTest runs this suite."""
import asyncio
import json
import os
import pathlib
import subprocess

import pytest

JAR = os.environ.get("GCNC_JAR", str(pathlib.Path(__file__).resolve().parents[3] / "build" / "libs" / "gcnc.jar"))
# a short-lived JVM: C1 alone starts faster (as scripts/gcnc does for small files)
JAVA = ["java", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-Xshare:auto"]
SERVER = JAVA + ["-jar", JAR, "lsp"]


def gcnc_json(command, path, *options):
    """`gcnc COMMAND --format json FILE` run in the file's folder, as the server checks the buffer there."""
    p = pathlib.Path(path)
    out = subprocess.run(JAVA + ["-jar", JAR, command, "--format", "json", *options, p.name], cwd=p.parent,
                         capture_output=True, text=True, check=False)
    return json.loads(out.stdout)["diagnostics"]


@pytest.fixture
def folder(tmp_path):
    return tmp_path


def make_client():
    """pytest-lsp's client, whose publishDiagnostics handler also keeps each buffer's version."""
    from lsprotocol import types
    from pytest_lsp import client as c

    features = dict(c.DEFAULT_CLIENT_FEATURES)

    def publish(client: c.LanguageClient, params: types.PublishDiagnosticsParams):
        client.diagnostics[params.uri] = params.diagnostics
        client.last_version[params.uri] = params.version
        client.publishes += 1
        client.published.set()

    def register(client: c.LanguageClient, params: types.RegistrationParams):
        client.registrations.extend(params.registrations)  # the watched files (pygls has no handler of its own)

    features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS] = publish
    features[types.CLIENT_REGISTER_CAPABILITY] = register
    client = c.LanguageClient(converter_factory=c.default_converter)
    client.last_version = {}
    client.publishes = 0
    client.registrations = []
    client.published = asyncio.Event()
    c.register_lsp_features(client, features)
    return client


async def until(client, predicate, timeout=20.0):
    """Waits until `predicate()` holds after a publishDiagnostics (the handler and this run on one loop)."""
    loop = asyncio.get_running_loop()
    end = loop.time() + timeout
    while not predicate():
        client.published.clear()
        left = end - loop.time()
        if left <= 0:
            raise AssertionError("no such diagnostics within %.0f s: %r" % (timeout, client.diagnostics))
        try:
            await asyncio.wait_for(client.published.wait(), left)
        except asyncio.TimeoutError:
            pass
