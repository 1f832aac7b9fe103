#!/usr/bin/env bash
# Installs what gcnc needs on a fresh Debian 12 machine with JDK 17: Debian's Gradle (4.4.1), and
# Chromium with its driver for the studio's browser tests (src/test/java/gcnc/studio, docs/studio.md),
# socat for the virtual controller's pty tests, and a C compiler for the resident checker's client.
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
if [ ${#need[@]} -gt 0 ]; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        command -v sudo >/dev/null 2>&1 || { echo "setup.sh: needs ${need[*]} from apt: run it as root or install sudo" >&2; exit 2; }
        sudo="sudo"
    fi
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi
java -version 2>&1 | grep -q '"17' || { echo "setup.sh: gcnc needs JDK 17 (java -version)" >&2; exit 2; }
