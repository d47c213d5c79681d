#!/usr/bin/env python3
"""Memory soak of `confvis walk` (by hand, never run by the tests; issue 24).

Walks a display for many frames with small walls while the head path makes the map follower
re-bake in the background, and samples the walk's resident memory (VmRSS from /proc/PID/status)
every --every frames. A leak shows as RSS growing with the frame count; the verdict compares
the RSS at --baseline-frame (default 1000: caches, the first bakes and the scene are settled by
then) with the RSS at the last frame, and fails (exit 1) when the end is more than --tolerance
percent (default 5) above it. Frame directories are removed as the walk goes (10 000 frames
of EXR + PNG would fill gigabytes); walk.json is kept.

  python3 tools/soak/walk_soak.py                       # 10 000 frames, 96-pixel walls
  python3 tools/soak/walk_soak.py --frames 2000 --every 50 --csv rss.csv

Run it niced on a shared machine (nice -n 10). Prints one line per sample (frame, seconds,
RSS in MiB, re-bakes so far) and the verdict.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

FRAME_LINE = re.compile(r"^frame (\d+)/(\d+) .*?(\[re-bake started\])?\s*$")


def rss_kib(pid):
    """VmRSS of a live process in KiB (None once it is gone)."""
    try:
        with open(f"/proc/{pid}/status") as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except FileNotFoundError:
        return None
    return None


def prune_frames(output, keep_from):
    """Removes frame-NNNN directories below keep_from (the walk has written them already)."""
    for name in os.listdir(output):
        if name.startswith("frame-") and name[6:].isdigit() and int(name[6:]) < keep_from:
            shutil.rmtree(os.path.join(output, name), ignore_errors=True)


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--confvis", default=os.path.join(root, "build", "confvis"),
                        help="the confvis binary")
    parser.add_argument("--config", default=os.path.join(root, "configs", "cave5.json"),
                        help="display config (cave5: five 1920-pixel walls)")
    parser.add_argument("--path", default=os.path.join(root, "configs", "paths", "cave-walk.csv"),
                        help="head path CSV (looped); cave-walk steps 40 cm, so it re-bakes")
    parser.add_argument("--frames", type=int, default=10000, help="frames to walk")
    parser.add_argument("--every", type=int, default=100, help="sample RSS every N frames")
    parser.add_argument("--scale", type=float, default=0.05,
                        help="wall resolution factor (0.05: 96-pixel cave5 walls)")
    parser.add_argument("--bake-resolution", type=int, default=32,
                        help="cube texels per face of the re-bakes (small: many re-bakes)")
    parser.add_argument("--radius", type=float, default=0.10,
                        help="metres the head may stray before a re-bake")
    parser.add_argument("--fps", type=float, default=30.0, help="frames per second of path time")
    parser.add_argument("--no-pacing", action="store_true",
                        help="render as fast as possible (fewer re-bakes finish per frame)")
    parser.add_argument("--baseline-frame", type=int, default=1000,
                        help="the frame whose RSS the end is compared with")
    parser.add_argument("--tolerance", type=float, default=5.0,
                        help="percent the end may exceed the baseline")
    parser.add_argument("--csv", help="also write frame,seconds,rss_kib,rebakes to this file")
    parser.add_argument("-o", "--output", help="walk output directory (default: a temporary one, "
                        "removed at the end)")
    args = parser.parse_args()
    if args.frames < args.baseline_frame + args.every:
        parser.error("--frames must exceed --baseline-frame by at least --every")

    output = args.output or tempfile.mkdtemp(prefix="confvis-soak-")
    cache = tempfile.mkdtemp(prefix="confvis-soak-cache-")  # every bake really runs
    command = [args.confvis, "walk", args.config, "--path", args.path,
               "--frames", str(args.frames), "--scale", str(args.scale),
               "--bake-resolution", str(args.bake_resolution), "--radius", str(args.radius),
               "--fps", str(args.fps), "-o", output]
    if args.no_pacing:
        command.append("--no-pacing")
    print("soak:", " ".join(command), flush=True)
    start = time.monotonic()
    walk = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=dict(os.environ, CONFVIS_CACHE_DIR=cache))
    samples, rebakes, last_frame, tail = [], 0, 0, []
    for line in walk.stderr:
        match = FRAME_LINE.match(line)
        if not match:
            tail = (tail + [line.rstrip()])[-20:]
            continue
        last_frame = int(match.group(1))
        rebakes += 1 if match.group(3) else 0
        if last_frame % args.every == 0 or last_frame == args.frames:
            rss = rss_kib(walk.pid)
            if rss is None:
                break
            seconds = time.monotonic() - start
            samples.append((last_frame, seconds, rss, rebakes))
            print(f"frame {last_frame:6d}  {seconds:8.1f} s  RSS {rss / 1024:8.1f} MiB  "
                  f"re-bakes started {rebakes}", flush=True)
            prune_frames(output, last_frame - 1)
    stdout = walk.stdout.read()
    status = walk.wait()
    elapsed = time.monotonic() - start
    shutil.rmtree(cache, ignore_errors=True)
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("frame,seconds,rss_kib,rebakes_started\n")
            f.writelines(f"{fr},{s:.2f},{r},{b}\n" for fr, s, r, b in samples)
    if not args.output:
        shutil.rmtree(output, ignore_errors=True)
    if status != 0 or last_frame != args.frames:
        print(f"soak: the walk ended with status {status} at frame {last_frame}:\n" +
              "\n".join(tail), file=sys.stderr)
        return 2
    print(stdout.strip())
    baseline = next((s for s in samples if s[0] >= args.baseline_frame), None)
    end = samples[-1]
    growth = 100.0 * (end[2] - baseline[2]) / baseline[2]
    peak = max(s[2] for s in samples)
    print(f"soak: {args.frames} frames in {elapsed:.0f} s, {rebakes} re-bakes started; "
          f"RSS at frame {baseline[0]}: {baseline[2] / 1024:.1f} MiB, at frame {end[0]}: "
          f"{end[2] / 1024:.1f} MiB ({growth:+.2f} %), peak {peak / 1024:.1f} MiB")
    if growth > args.tolerance:
        print(f"soak: FAIL: RSS grew {growth:.2f} % (> {args.tolerance} %)")
        return 1
    print(f"soak: PASS (within {args.tolerance} %)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
