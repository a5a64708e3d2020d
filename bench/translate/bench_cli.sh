#!/bin/sh
# bench_cli.sh: raygl2pov -j 1 on the strips trace, files written, through
# the real command line; two binaries side by side in one run.
#
#   bench/translate/bench_cli.sh BUILD [BASE_RAYGL2POV] [RUNS]
#
# BUILD is this tree's build directory (its bench_translate writes the trace
# and times the printf baseline; its raygl2pov is "new"). BASE_RAYGL2POV is
# another raygl2pov to compare with, e.g. main's built apart:
#   git archive main | tar -x -C /tmp/base && (cd /tmp/base && meson setup build &&
#   ninja -C build translate/raygl2pov)
# RUNS (default 7, at least 5) runs of each binary, interleaved, each into a
# fresh output directory (a rerun into a full one also compares the old
# files). Reported: medians of CPU time (user + system of the child, from
# wait4) and wall time, in M vertices sent per second. Figures only.
set -eu
build=${1:?usage: bench_cli.sh BUILD [BASE_RAYGL2POV] [RUNS]}
base=${2:-}
runs=${3:-7}
[ "$runs" -ge 5 ] || runs=5
tmp=$(mktemp -d /tmp/rgl-bench-cli-XXXXXX)
trap 'rm -rf "$tmp"' EXIT INT TERM
verts=$("$build/bench/translate/bench_translate" --write-trace "$tmp/strips.raygl")
printf_s=$("$build/bench/translate/bench_translate" --printf-positions --runs "$runs" 2>/dev/null)
python3 - "$tmp" "$verts" "$runs" "$printf_s" "$build/translate/raygl2pov" $base <<'EOF'
import os, shutil, statistics, subprocess, sys, time
tmp, verts, runs, printf_s = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
bins = [("new", sys.argv[5])] + ([("base", sys.argv[6])] if len(sys.argv) > 6 else [])
res = {name: ([], [], [], []) for name, _ in bins}
size = {}
for k in range(runs):
    for name, exe in (bins if k % 2 == 0 else bins[::-1]):
        out = os.path.join(tmp, "out-" + name)
        shutil.rmtree(out, ignore_errors=True)
        t0 = time.monotonic()
        p = subprocess.Popen([exe, "-j", "1", "-q", os.path.join(tmp, "strips.raygl"), "-o", out])
        _, status, ru = os.wait4(p.pid, 0)
        wall = time.monotonic() - t0
        if status != 0:
            sys.exit("bench_cli: %s failed (status %d)" % (exe, status))
        res[name][0].append(ru.ru_utime + ru.ru_stime)
        res[name][1].append(wall)
        res[name][2].append(ru.ru_utime)
        res[name][3].append(ru.ru_stime)
        size[name] = sum(os.path.getsize(os.path.join(out, f)) for f in os.listdir(out))
print("raygl2pov -j 1, strips trace: 4 frames, %d vertices sent; medians of %d runs"
      % (verts, runs))
print("  printf %%.9g of the positions alone: %.3f s CPU  %5.2f M vertices/s" %
      (printf_s, verts / printf_s / 1e6))
med = {}
for name, exe in bins:
    cpu, wall = statistics.median(res[name][0]), statistics.median(res[name][1])
    med[name] = (cpu, wall)
    print("  %-4s %s: %.3f s CPU %5.2f M vertices/s, %.3f s wall %5.2f M vertices/s, "
          "%.1f MB written, CPU %.2fx printf" % (name, exe, cpu, verts / cpu / 1e6, wall,
          verts / wall / 1e6, size[name] / 1e6, cpu / printf_s))
    print("       user %.3f s, system %.3f s" % (statistics.median(res[name][2]),
          statistics.median(res[name][3])))
if "base" in med:
    print("  new/base speed: %.2fx CPU, %.2fx wall" % (med["base"][0] / med["new"][0],
          med["base"][1] / med["new"][1]))
EOF
