#!/usr/bin/env bash
# Installs what gcnc needs on a fresh Debian 12 machine with JDK 17: Debian's Gradle (4.4.1), and
# Chromium with its driver for the studio's browser tests (src/test/java/gcnc/studio, docs/studio.md),
# socat for the virtual controller's pty tests, a C compiler for the resident checker's client, and Neovim and
# pytest-lsp (a venv, .venv-lsp) for the language server's real-client tests (docs/editors.md).
# Safe to run again; it installs nothing that is already there.
set -eu
need=()
command -v gradle >/dev/null 2>&1 || need+=(gradle)
command -v java >/dev/null 2>&1 || need+=(openjdk-17-jdk-headless)
command -v chromium >/dev/null 2>&1 || need+=(chromium)
command -v chromedriver >/dev/null 2>&1 || need+=(chromium-driver)
# socat makes the pty pairs of the virtual controller's serial tests (docs/virtual-controller.md) and
# of gcnc run's (RunOnControllerTest, docs/run.md)
command -v socat >/dev/null 2>&1 || need+=(socat)
# gcc compiles the resident checker's client (scripts/gcnc-client.c: install.sh, ResidentCheckerTest)
command -v cc >/dev/null 2>&1 || need+=(gcc)
# the language server's real clients (LspClientTest, docs/editors.md): Neovim's own, and Python's venv for pytest-lsp
command -v nvim >/dev/null 2>&1 || need+=(neovim)
python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || need+=(python3-venv)
# a font for the setup sheet's PNG (gcnc sheet -o sheet.png: Java 2D draws its text with the system's fonts)
[ -e /usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf ] || need+=(fonts-dejavu-core)
command -v fc-list >/dev/null 2>&1 || need+=(fontconfig)
if [ ${#need[@]} -gt 0 ]; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        command -v sudo >/dev/null 2>&1 || { echo "setup.sh: needs ${need[*]} from apt: run it as root or install sudo" >&2; exit 2; }
        sudo="sudo"
    fi
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi
# pytest-lsp (PyPI, pygls's client) in a virtual environment of the checkout's own, .venv-lsp (not in build/,
# which gradle clean removes): LspClientTest runs src/test/lsp with it, and skips, saying so, without it
here=$(cd "$(dirname "$0")" && pwd)
if [ ! -x "$here/.venv-lsp/bin/python" ] || ! "$here/.venv-lsp/bin/python" -c 'import pytest_lsp' >/dev/null 2>&1; then
    python3 -m venv "$here/.venv-lsp"
    "$here/.venv-lsp/bin/pip" install -q 'pytest-lsp==1.0.1'
fi
java -version 2>&1 | grep -q '"17' || { echo "setup.sh: gcnc needs JDK 17 (java -version)" >&2; exit 2; }
