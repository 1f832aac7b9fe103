#!/usr/bin/env bash
# End-to-end test of the Gradle plugin as a shop meets it (docs/gradle-plugin.md):
#   1. publishes the gcnc library and plugin to a throwaway Maven local repository
#      (skipped with --repo DIR: DIR already holds them, as the root build's ShopProjectTest arranges);
#   2. builds a copy of samples/shop-project: it must pass, write the Galil programs and run the shop's
#      JUnit tests (gcnc's fixtures: one test per program, and the pin's own);
#   3. a copy with a warning: the log shows it once though three tasks judge the program;
#      builds the clean copy again: gcncCheck, gcncCompile, gcncSimulate and the shop's tests must be UP-TO-DATE;
#      then edits a program so that it stays clean but breaks the shop's staysWithin assertion: the
#      shop's tests must run again and fail (the plugin declares the programs as their inputs);
#   4. builds a copy with a faulty program: it must fail at that program's line and column, and the
#      shop's JUnit test of that program must fail too;
#   5. gcnc { stock } (stage stock): a blank without units read in an inch program's inches, on the setup
#      sheet and placing the work zero; a bad one fails the task with the command line's message;
#   6. a shop's library (stage library): a copy with a program that calls O9010.nc beside it, through a
#      build cache of its own: an edit of the called file judges it and its caller again and keeps the
#      other results; a second clone with the same build cache takes gcncCheck and gcncCompile FROM-CACHE;
#      a removed program's findings and outputs are gone, nothing else judged again.
# Each stage prints "== stage NAME" and Gradle's output; the last line is "shop-project: all passed"
# or the script exits 1 at the first outcome that is wrong.
# Usage: scripts/shop-project-test.sh [--repo DIR] [--keep]
set -u
root="$(cd "$(dirname "$0")/.." && pwd)"
repo=""
keep=0
while [ $# -gt 0 ]; do
    case "$1" in
        --repo) repo="$(cd "$2" && pwd)" || exit 2; shift 2 ;;
        --keep) keep=1; shift ;;
        *) echo "usage: $0 [--repo DIR] [--keep]" >&2; exit 2 ;;
    esac
done
command -v gradle >/dev/null 2>&1 || { echo "shop-project: gradle is not on PATH" >&2; exit 2; }
work="$(mktemp -d "${TMPDIR:-/tmp}/gcnc-shop.XXXXXX")"
[ "$keep" = 1 ] && echo "shop-project: working in $work" || trap 'rm -rf "$work"' EXIT

fail() { echo "shop-project: FAILED: $*" >&2; exit 1; }
# gradle in a project folder, against the repository; its output to stdout and to $work/last.log.
# Through a Gradle daemon: the six builds share one warm JVM instead of starting (and warming) one
# each (a third of this script's time, issue 23). It may be one already idle on this machine;
# one started here stops by itself after a minute with nothing to do (CI leaves none behind).
# The daemon's JVM: C1 alone and the serial collector, as for the test JVMs (build.gradle): twelve
# short builds spend most of a default JVM's CPU on the C2 compiler warming code that runs a few times.
daemon_jvm="-Xmx512m -XX:TieredStopAtLevel=1 -XX:+UseSerialGC"
# and the same for each build's short-lived client JVM (Debian's gradle script reads GRADLE_OPTS)
export GRADLE_OPTS="${GRADLE_OPTS:-} -XX:TieredStopAtLevel=1 -XX:+UseSerialGC"
run() {
    local dir="$1"; shift
    gradle --daemon -Dorg.gradle.daemon.idletimeout=60000 "-Dorg.gradle.jvmargs=$daemon_jvm" --console=plain -p "$dir" -Dmaven.repo.local="$repo" "$@" 2>&1 \
        | tee "$work/last.log"
    return "${PIPESTATUS[0]}"
}

if [ -z "$repo" ]; then
    repo="$work/m2"
    echo "== stage publish"
    run "$root" publishToMavenLocal || fail "gradle publishToMavenLocal"
fi
[ -f "$repo/gcnc/lathe/gcnc.lathe.gradle.plugin/0.1.0/gcnc.lathe.gradle.plugin-0.1.0.pom" ] || fail "no plugin marker gcnc.lathe in $repo"
[ -f "$repo/gcnc/gcnc.gradle.plugin/0.1.0/gcnc.gradle.plugin-0.1.0.pom" ] || fail "no plugin marker gcnc (the alias) in $repo"

mkdir "$work/clean" "$work/faulty"
(cd "$root/samples/shop-project" && tar --exclude=build --exclude=.gradle -cf - .) | tar -xf - -C "$work/clean"
(cd "$work/clean" && tar -cf - .) | tar -xf - -C "$work/faulty"

echo "== stage clean"
run "$work/clean" check gcncCompile gcncSimulate || fail "the clean sample did not build"
for p in o1201-pin o1202-spacer ops/o1203-groove; do
    [ -s "$work/clean/build/gcnc/$p.dmc" ] && [ -s "$work/clean/build/gcnc/$p.dmc.map" ] || fail "no build/gcnc/$p.dmc(.map)"
    for x in svg html png; do
        [ -s "$work/clean/build/reports/gcnc/gcncSimulate/$p.$x" ] || fail "no build/reports/gcnc/gcncSimulate/$p.$x"
    done
done
python3 - "$work/clean/build/test-results/junit-platform" <<'PY' || fail "the shop's JUnit tests (gcnc fixtures) did not all run and pass"
import glob, sys, xml.etree.ElementTree as ET
cases = [c for f in glob.glob(sys.argv[1] + "/*.xml") for c in ET.parse(f).getroot().iter("testcase")]
bad = [c for c in cases if c.find("failure") is not None or c.find("error") is not None]
sys.exit(0 if len(cases) == 4 and not bad else 1)  # one per program (3) and the pin's own
PY
for t in gcncCheck gcncCompile gcncSimulate; do
    grep -q '"errors": 0' "$work/clean/build/reports/gcnc/$t.json" || fail "no clean build/reports/gcnc/$t.json"
    grep -q '"version": "2.1.0"' "$work/clean/build/reports/gcnc/$t.sarif" || fail "no SARIF build/reports/gcnc/$t.sarif"
done

echo "== stage warned"
# A program with a warning (E646: a cut with tool offset 00): gcncCheck, gcncCompile and gcncSimulate
# each judge it, and the build's log shows the warning once, not once per task.
mkdir "$work/warned"
(cd "$work/clean" && tar --exclude=build --exclude=.gradle -cf - .) | tar -xf - -C "$work/warned"
sed 's/^T101$/T100/' "$work/clean/src/main/gcode/o1201-pin.gcode" > "$work/warned/src/main/gcode/o1201-pin.gcode"
run "$work/warned" gcncCheck gcncCompile gcncSimulate || fail "the build with a warning failed"
n=$(grep -c "o1201-pin.gcode:10:1: warning\[E646\]" "$work/last.log")
[ "$n" = 1 ] || fail "the warning at o1201-pin.gcode:10:1 was printed $n times (once is right)"
for t in gcncCheck gcncCompile gcncSimulate; do
    grep -q '"code": "E646"' "$work/warned/build/reports/gcnc/$t.json" || fail "$t.json does not list the warning"
done

echo "== stage again"
run "$work/clean" check gcncCompile gcncSimulate || fail "the second build failed"
for t in gcncCheck gcncCompile gcncSimulate junitPlatformTest; do
    grep -q "^:$t UP-TO-DATE" "$work/last.log" || fail "$t was not UP-TO-DATE on the second run"
done

echo "== stage edited"
# The pin's roughing pass now goes to Z-35: still a clean program (gcncCheck passes), but behind the
# Z-30 the shop's staysWithin assertion allows. The shop's tests must run again and fail, never stay
# UP-TO-DATE because only a program (not a test class) changed.
sed -i 's/^G01 Z-25\. F0\.25$/G01 Z-35. F0.25/' "$work/clean/src/main/gcode/o1201-pin.gcode"
grep -q '^G01 Z-35\. F0\.25$' "$work/clean/src/main/gcode/o1201-pin.gcode" || fail "the pin's program was not edited"
if run "$work/clean" check; then
    fail "the build passed after an edit that breaks the shop's staysWithin assertion"
fi
grep -q "^:junitPlatformTest UP-TO-DATE" "$work/last.log" && fail "junitPlatformTest stayed UP-TO-DATE after a program changed"
grep -q "^:gcncCheck$" "$work/last.log" || fail "gcncCheck did not run again after a program changed"
python3 - "$work/clean/build/test-results/junit-platform" <<'PY' || fail "the pin's staysWithin test did not fail"
import glob, sys, xml.etree.ElementTree as ET
cases = [c for f in glob.glob(sys.argv[1] + "/*.xml") for c in ET.parse(f).getroot().iter("testcase")]
bad = [c.get("name") for c in cases if c.find("failure") is not None]
sys.exit(0 if bad == ["thePinIsQuickAndKeepsClearOfTheJaws()"] else 1)
PY

echo "== stage faulty"
# Line 6 feeds before the spindle turns: E051 at 6:1.
cat > "$work/faulty/src/main/gcode/o1299-faulty.gcode" <<'NC'
O1299 (FAULTY: FEED MOVE BEFORE THE SPINDLE RUNS)
G21 G18 G99
G28 U0. W0.
T101
G54 G00 X44. Z2.
G01 X40. F0.2
M05
M30
NC
# --continue: the shop's JUnit test of every program must fail on it too, not only gcncCheck.
if run "$work/faulty" check --continue; then
    fail "the build with a faulty program passed"
fi
python3 - "$work/faulty/build/test-results/junit-platform" <<'PY' || fail "no failing JUnit test named o1299-faulty.gcode"
import glob, sys, xml.etree.ElementTree as ET
cases = [c for f in glob.glob(sys.argv[1] + "/*.xml") for c in ET.parse(f).getroot().iter("testcase")]
bad = [c.find("failure").get("message") or "" for c in cases if c.find("failure") is not None]
sys.exit(0 if len(bad) == 1 and "o1299-faulty.gcode:6:1: error[E051]" in bad[0] else 1)
PY
grep -q "src/main/gcode/o1299-faulty.gcode:6:1: error\[E051\]" "$work/last.log" || fail "no error at o1299-faulty.gcode:6:1"
grep -q "see the report at file://.*/build/reports/gcnc/gcncCheck.html" "$work/last.log" || fail "no link to the HTML report"
grep -q '<td>6:1</td><td class="error">error</td><td>E051</td>' "$work/faulty/build/reports/gcnc/gcncCheck.html" \
    || fail "the HTML report does not show the error at o1299-faulty.gcode:6:1"
grep -q '"version": "0.1.0"' "$work/faulty/build/reports/gcnc/gcncCheck.json" || fail "the JSON report does not carry gcnc's version"

echo "== stage ignoreFailures"
printf '\ngcnc { ignoreFailures = true }\n' >> "$work/faulty/build.gradle"
run "$work/faulty" gcncCheck || fail "gcncCheck failed with ignoreFailures = true"
grep -q "gcncCheck: 1 error in 1 program of 4; see the report at .*(ignoreFailures = true: the build goes on)" "$work/last.log" \
    || fail "ignoreFailures did not say what it let through"
python3 - "$work/faulty/build/reports/gcnc/gcncCheck.sarif" <<'PY' || fail "the SARIF report does not hold the error at o1299-faulty.gcode:6:1"
import json, sys
r = json.load(open(sys.argv[1]))["runs"][0]["results"]
loc = [(x["ruleId"], x["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
        x["locations"][0]["physicalLocation"]["region"]["startLine"]) for x in r]
sys.exit(0 if loc == [("E051", "src/main/gcode/o1299-faulty.gcode", 6)] else 1)
PY
echo "== stage stock"
# gcnc { stock } as gcnc compile --stock takes it: values without a unit in the program's own units
# (G20 here: inches), the blank on the setup sheet and the work zero on its face (E662); a bore as
# wide as the bar fails the task with the command line's message.
mkdir "$work/stock"
(cd "$root/samples/shop-project" && tar --exclude=build --exclude=.gradle -cf - .) | tar -xf - -C "$work/stock"
cat > "$work/stock/src/main/gcode/o1205-inch.gcode" <<'NC'
O1205 (BUSHING BLANK - 1.75 IN BAR, FACE)
G20 G18 G40 G99
G28 U0. W0.
T101
G50 S2500
G96 S600 M03
G54 G00 X1.8 Z0.1 M08
G01 Z0. F0.008
X-0.06 F0.006
G00 Z0.1
M09
G28 U0. W0.
M05
M30
NC
printf "\ngcnc { stock = '1.75,4,2'; programs = files('src/main/gcode/o1205-inch.gcode') }\n" >> "$work/stock/build.gradle"
run "$work/stock" gcncCompile gcncSimulate --info || fail "the build with gcnc { stock } failed"
grep -q "o1205-inch.gcode: stock 1.75,4,2 read in inches (G20 at line 2)" "$work/last.log" \
    || fail "gcnc { stock } did not say it read 1.75,4,2 in the program's inches"
grep -q "Blank</th><td>diameter 1.75 in (44.45 mm), length 4 in (101.6 mm); sticks out 2 in (50.8 mm) from the jaws' face" \
    "$work/stock/build/reports/gcnc/gcncSimulate/o1205-inch.html" || fail "the setup sheet does not show the blank of gcnc { stock }"
grep -q '"code": "E662"' "$work/stock/build/reports/gcnc/gcncCompile.json" || fail "gcncCompile did not put the work zero on the given blank's face (E662)"
[ -s "$work/stock/build/gcnc/o1205-inch.dmc" ] || fail "no build/gcnc/o1205-inch.dmc with gcnc { stock }"
sed -i "s/stock = '1.75,4,2'/stock = '65,150,100,65'/" "$work/stock/build.gradle"
if run "$work/stock" gcncCompile; then
    fail "gcncCompile passed with a bore as wide as the bar"
fi
grep -q "gcncCompile: gcnc { stock }: the bore 65 must be smaller than the diameter 65" "$work/last.log" \
    || fail "a bad gcnc { stock } did not fail with --stock's message"

echo "== stage library"
# The bushing faces, then calls O9010 in the file beside it (M98 P9010); T100 is a warning (E646) of its own.
mkdir "$work/library"
(cd "$root/samples/shop-project" && tar --exclude=build --exclude=.gradle -cf - .) | tar -xf - -C "$work/library"
cat > "$work/library/src/main/gcode/ops/o1204-bushing.gcode" <<'NC'
O1204 (BUSHING - FACE, THEN THE RETRACT IN O9010)
G21 G18 G40 G99
G28 U0. W0.
T100
G50 S3000
G96 S200 M03
G54 G00 X44. Z2. M08
G01 Z0. F0.2
X-1.6
G00 Z2.
M98 P9010
M09
G28 U0. W0.
M05
M30
NC
cat > "$work/library/src/main/gcode/ops/O9010.nc" <<'NC'
O9010 (RETRACT CLEAR OF THE PART)
G21 G54 G00 X46. Z5.
M99
NC
printf '\nbuildCache { local(DirectoryBuildCache) { directory = new File("%s") } }\n' "$work/cache" \
    >> "$work/library/settings.gradle"
run "$work/library" gcncCheck gcncCompile --build-cache || fail "the library did not build"
grep -q "^gcncCheck: 5 programs checked" "$work/last.log" || fail "gcncCheck did not check the library's 5 programs"
grep -q "o1204-bushing.gcode:8:1: warning\[E646\]" "$work/last.log" || fail "no warning E646 of the bushing"
sed -i 's/Z5\.$/Z6./' "$work/library/src/main/gcode/ops/O9010.nc"
run "$work/library" gcncCheck gcncCompile --build-cache --info || fail "the library did not build after an edit of O9010.nc"
for t in gcncCheck gcncCompile; do
    grep -q "^$t: 2 programs judged again (changed, new, or calling a file that changed), 3 kept from the last run" \
        "$work/last.log" || fail "$t did not judge only the edited O9010.nc and its caller again"
    grep -q "^$t: judged again: src/main/gcode/ops/O9010.nc, src/main/gcode/ops/o1204-bushing.gcode$" "$work/last.log" \
        || fail "$t judged other programs again than O9010.nc and o1204-bushing.gcode"
done
grep -c "o1204-bushing.gcode:8:1: warning\[E646\]" "$work/last.log" | grep -qx 1 || fail "the kept warning was not printed once"
mkdir "$work/library2"
(cd "$work/library" && tar --exclude=build --exclude=.gradle -cf - .) | tar -xf - -C "$work/library2"
run "$work/library2" gcncCheck gcncCompile --build-cache || fail "the second clone did not build"
for t in gcncCheck gcncCompile; do
    grep -q "^:$t FROM-CACHE" "$work/last.log" || fail "$t was not taken from the build cache in a second clone"
done
cmp -s "$work/library/build/reports/gcnc/gcncCheck.json" "$work/library2/build/reports/gcnc/gcncCheck.json" \
    || fail "the second clone's gcncCheck.json is not the first's"
[ -s "$work/library2/build/gcnc/ops/o1204-bushing.dmc" ] || fail "no build/gcnc/ops/o1204-bushing.dmc from the cache"
rm "$work/library2/src/main/gcode/ops/o1204-bushing.gcode"
run "$work/library2" gcncCheck gcncCompile --build-cache || fail "the second clone did not build without the bushing"
grep -q "^gcncCheck: 0 programs judged again (changed, new, or calling a file that changed), 4 kept from the last run" \
    "$work/last.log" || fail "removing the bushing judged other programs again"
grep -q "o1204-bushing" "$work/library2/build/reports/gcnc/gcncCheck.json" && fail "the removed bushing's findings are still in gcncCheck.json"
grep -q '"code": "E139"' "$work/library2/build/reports/gcnc/gcncCheck.json" || fail "O9010.nc's own finding (E139) is gone"
[ -e "$work/library2/build/gcnc/ops/o1204-bushing.dmc" ] && fail "the removed bushing's .dmc is still in build/gcnc"
echo "shop-project: all passed"
