#!/usr/bin/env bash
# A shop's whole library through the Gradle plugin (docs/gradle-plugin.md, "A shop's whole library"):
# PROGRAMS small part programs (bench/gen_library.py, default 10,000: folders of 100, each with 4
# subprogram files O9001.nc.. that every 10th program calls with M98) checked by `gradle gcncCheck`
#   1. cold: no results, an empty build cache;
#   2. after one edit of one called file: only it and its callers are judged again (the count printed);
#   3. a fresh clone (the project copied to a new folder, no build/) with the same build cache: FROM-CACHE.
# Each run's wall time is Gradle's whole invocation (through one Gradle daemon, started by the first run:
# its start-up is in the cold figure). Prints `uptime` before and after: the machine is shared, the
# figures are its load's. The plugin is published to a throwaway Maven repository first (or --repo DIR).
# usage: bench/library.sh [PROGRAMS] [--repo DIR] [--workers N]   (VERIFY=1: also judge the edited
#        library afresh in a third copy, one thread, and compare its JSON report with the incremental one)
set -eu
cd "$(dirname "$0")/.."
root=$(pwd)
programs=10000; repo=""; workers=""
while [ $# -gt 0 ]; do
    case "$1" in
        --repo) repo="$(cd "$2" && pwd)"; shift 2 ;;
        --workers) workers="--max-workers=$2"; shift 2 ;;
        *) programs=$1; shift ;;
    esac
done
out="$root/bench/out/library"
rm -rf "$out"; mkdir -p "$out"
gradle_() {
    local dir=$1; shift
    gradle --daemon -Dorg.gradle.daemon.idletimeout=120000 --console=plain -p "$dir" -Dmaven.repo.local="$repo" \
        $workers "$@" > "$out/last.log" 2>&1 || { cat "$out/last.log"; echo "library: gradle failed in $dir" >&2; exit 1; }
}
timed() {  # timed NAME DIR ARGS...: runs gradle, prints the wall time
    local name=$1 dir=$2; shift 2
    local t0 t1
    t0=$(date +%s.%N); gradle_ "$dir" "$@"; t1=$(date +%s.%N)
    cp "$out/last.log" "$out/$name.log"
    printf '%-8s %7.1f s wall   ' "$name" "$(echo "$t1 - $t0" | bc)"
}
if [ -z "$repo" ]; then
    repo="$out/m2"
    gradle -q --console=plain -Dmaven.repo.local="$repo" publishToMavenLocal > "$out/publish.log" 2>&1 \
        || { cat "$out/publish.log"; exit 1; }
fi
project="$out/shop"
mkdir -p "$project"
python3 bench/gen_library.py "$programs" "$project"
cat > "$project/settings.gradle" <<GRADLE
pluginManagement { repositories { mavenLocal(); mavenCentral() } }
rootProject.name = 'library'
buildCache { local(DirectoryBuildCache) { directory = new File('$out/cache') } }
GRADLE
cat > "$project/build.gradle" <<'GRADLE'
plugins { id 'gcnc.lathe' version '0.1.0' }
gcnc { machine = 'haas' }
GRADLE
echo "library: $programs programs under $project ($(find "$project/src" -name 'O9*.nc' | wc -l) of them called files), load: $(uptime)"
timed cold "$project" gcncCheck --build-cache
grep "^gcncCheck: .* checked" "$out/cold.log"
sed -i 's/Z5\.$/Z5.5/' "$project/src/main/gcode/cell000/O9001.nc"
timed edit "$project" gcncCheck --build-cache --info
grep "^gcncCheck: .* judged again" "$out/edit.log"
grep "^gcncCheck: judged again:" "$out/edit.log" | cut -c1-300
clone="$out/clone"
mkdir -p "$clone"
(cd "$project" && tar --exclude=build --exclude=.gradle -cf - .) | tar -xf - -C "$clone"
timed clone "$clone" gcncCheck --build-cache
grep -q "^:gcncCheck FROM-CACHE" "$out/clone.log" && echo "gcncCheck FROM-CACHE" || { echo "gcncCheck NOT from the cache"; exit 1; }
cmp -s "$project/build/reports/gcnc/gcncCheck.json" "$clone/build/reports/gcnc/gcncCheck.json" \
    || { echo "library: the clone's report differs from the project's" >&2; exit 1; }
if [ "${VERIFY:-0}" = 1 ]; then
    fresh="$out/fresh"
    mkdir -p "$fresh"
    (cd "$project" && tar --exclude=build --exclude=.gradle -cf - .) | tar -xf - -C "$fresh"
    workers="--max-workers=1"
    timed fresh "$fresh" gcncCheck --no-build-cache
    echo
    for r in json sarif html; do
        cmp -s "$project/build/reports/gcnc/gcncCheck.$r" "$fresh/build/reports/gcnc/gcncCheck.$r" \
            && echo "gcncCheck.$r: the incremental, parallel run's is the one-thread full run's" \
            || { echo "library: gcncCheck.$r of the incremental run differs from a full run's" >&2; exit 1; }
    done
fi
echo "load: $(uptime)"
