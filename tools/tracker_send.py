#!/usr/bin/env python3
"""Sends head poses to a confvis live tracker by hand (confvis view --tracker dtrack:PORT|udp:PORT).

By default a head 1.7 m above the floor circles the reference point (radius --radius metres,
one turn per --period seconds), always facing the centre of the room; --fixed X,Y,Z sends one
pose standing still instead. Poses are written in confvis' room frame (metres, +y up, -z
forward), so use a display config without a "tracking" section, or one whose transform is the
identity, to see them unchanged. --protocol dtrack writes ART DTrack2 ASCII frames
(millimetres, column-wise rotation matrix, body --body); --protocol json writes JSON lines.
"""
import argparse
import json
import math
import socket
import sys
import time


def yaw_matrix_columns(yaw):
    """Column-wise 3x3 rotation about +y by `yaw` radians (DTrack's b0..b8)."""
    c, s = math.cos(yaw), math.sin(yaw)
    return [c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c]


def dtrack_frame(frame, seconds, body, position_m, yaw):
    x, y, z = (1000.0 * v for v in position_m)
    matrix = " ".join("%.6f" % v for v in yaw_matrix_columns(yaw))
    return ("fr %d\r\nts %.6f\r\n6dcal 1\r\n6d 1 [%d 1.000][%.3f %.3f %.3f 0.0000 0.0000 0.0000]"
            "[%s]\r\n" % (frame, seconds, body, x, y, z, matrix))


def json_line(seconds, position_m, yaw):
    quat = [0.0, math.sin(yaw / 2), 0.0, math.cos(yaw / 2)]  # [x, y, z, w]
    return json.dumps({"t": seconds, "pos": list(position_m), "quat": quat}) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--protocol", choices=["dtrack", "json"], default="json")
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=int, default=5000)
    parser.add_argument("--rate", type=float, default=60.0, help="poses per second (default 60)")
    parser.add_argument("--seconds", type=float, default=0.0,
                        help="stop after this long (default: run until Ctrl-C)")
    parser.add_argument("--radius", type=float, default=0.3, help="circle radius, metres")
    parser.add_argument("--period", type=float, default=10.0, help="seconds per turn")
    parser.add_argument("--height", type=float, default=0.2,
                        help="head height above the reference point, metres")
    parser.add_argument("--body", type=int, default=0, help="DTrack body id (default 0)")
    parser.add_argument("--fixed", help="one pose X,Y,Z (metres) instead of the circle")
    args = parser.parse_args()
    if not 1 <= args.port <= 65535 or args.rate <= 0 or args.period <= 0:
        parser.error("--port must be 1..65535, --rate and --period positive")
    fixed = None
    if args.fixed:
        try:
            fixed = [float(v) for v in args.fixed.split(",")]
        except ValueError:
            fixed = []
        if len(fixed) != 3 or not all(math.isfinite(v) for v in fixed):
            parser.error("--fixed wants X,Y,Z in metres, got %r" % args.fixed)

    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    start = time.monotonic()
    frame = 0
    print("sending %s poses to %s:%d at %g Hz (Ctrl-C stops)"
          % (args.protocol, args.host, args.port, args.rate), file=sys.stderr)
    try:
        while args.seconds <= 0 or time.monotonic() - start < args.seconds:
            t = time.monotonic() - start
            if fixed:
                position, yaw = fixed, 0.0
            else:
                angle = 2 * math.pi * t / args.period
                position = [args.radius * math.sin(angle), args.height,
                            args.radius * math.cos(angle)]
                yaw = angle  # faces the centre: forward (-z) turned by the angle points inward
            if args.protocol == "dtrack":
                packet = dtrack_frame(frame, t, args.body, position, yaw)
            else:
                packet = json_line(t, position, yaw)
            sock.sendto(packet.encode("ascii"), (args.host, args.port))
            frame += 1
            time.sleep(max(0.0, start + frame / args.rate - time.monotonic()))
    except KeyboardInterrupt:
        pass
    print("sent %d poses" % frame, file=sys.stderr)


if __name__ == "__main__":
    main()
