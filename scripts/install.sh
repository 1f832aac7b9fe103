#!/usr/bin/env bash
# Installs the gcnc command: PREFIX/bin/gcnc (the launcher scripts/gcnc) and PREFIX/lib/gcnc/gcnc.jar
# with a class-data-sharing archive made for that jar (gcnc.jsa), so that every run starts faster.
# usage: bash scripts/install.sh [--prefix DIR]     (default DIR: ~/.local; then PREFIX/bin on PATH)
# Safe to run again: it replaces the jar, the archive and the launcher. Builds the jar if needed.
set -eu
prefix="${HOME}/.local"
while [ $# -gt 0 ]; do
    case "$1" in
        --prefix) prefix="$2"; shift 2 ;;
        *) echo "usage: $0 [--prefix DIR]" >&2; exit 2 ;;
    esac
done
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
[ -f build/libs/gcnc.jar ] || gradle -q assemble
mkdir -p "$prefix/bin" "$prefix/lib/gcnc"
lib="$(cd "$prefix/lib/gcnc" && pwd)"
# Written beside and renamed into place: a run that starts meanwhile never sees half a jar.
cp build/libs/gcnc.jar "$lib/gcnc.jar.new" && mv -f "$lib/gcnc.jar.new" "$lib/gcnc.jar"
cp scripts/gcnc-client.py "$lib/gcnc-client.py.new" && mv -f "$lib/gcnc-client.py.new" "$lib/gcnc-client.py"
# The resident checker's client in C (no Python start-up: a few ms instead of 15-60) when there is a
# C compiler; else the launcher uses the Python client, which speaks the same protocol.
rm -f "$lib/gcnc-client"
if command -v "${CC:-cc}" >/dev/null 2>&1 && "${CC:-cc}" -O2 -o "$lib/gcnc-client.new" scripts/gcnc-client.c 2>/dev/null; then
    mv -f "$lib/gcnc-client.new" "$lib/gcnc-client"
else
    rm -f "$lib/gcnc-client.new"
    echo "gcnc: no C compiler: the resident checker's client is the Python one"
fi
cp scripts/gcnc "$prefix/bin/gcnc.new" && chmod 755 "$prefix/bin/gcnc.new" && mv -f "$prefix/bin/gcnc.new" "$prefix/bin/gcnc"
# The archive: the classes a check, a compile and a simulate load, dumped at the end of a training
# run over the installed jar (JDK 13+ dynamic archive). The JVM checks it against the jar's size and
# time at every start and ignores it if they differ, so a stale archive is slow, never wrong.
rm -f "$lib/gcnc.jsa"
train="$(mktemp -d)"
trap 'rm -rf "$train"' EXIT
cp samples/bishop.nc samples/turning.nc "$train/"
# A compile loads what a check does and the backend and simulator besides.
java -XX:ArchiveClassesAtExit="$lib/gcnc.jsa" -XX:+UseSerialGC -Xlog:cds=off -Xlog:cds+dynamic=off \
    -jar "$lib/gcnc.jar" compile "$train/turning.nc" -o "$train/turning.dmc" >/dev/null 2>&1 || true
[ -s "$lib/gcnc.jsa" ] && echo "gcnc: class-data archive $lib/gcnc.jsa" || echo "gcnc: no class-data archive (this JVM cannot make one); gcnc runs without it"
echo "gcnc: installed $prefix/bin/gcnc ($("$prefix/bin/gcnc" --version))"
case ":$PATH:" in
    *":$prefix/bin:"*) ;;
    *) echo "gcnc: add $prefix/bin to PATH, e.g. export PATH=\"$prefix/bin:\$PATH\"" ;;
esac
