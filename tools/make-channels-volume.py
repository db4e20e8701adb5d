#!/usr/bin/env python3
"""Writes a synthetic fluorescence stack with several channels as a raw NRRD, for measuring what
each added channel costs (issue 20): channel c holds a few soft blobs of its own (a nucleus-like
ball, smaller spots) over a dim noisy background, so that each channel's TF shows a different
part of the box and the rays see realistic empty space.

Usage: tools/make-channels-volume.py OUT.nrrd [CHANNELS (default 4)] [SIZE (default 128)] [SEED]
8-bit voxels, channel fastest (NRRD "kinds: list domain domain domain"). Pure Python.
"""
import math
import random
import sys


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    out = argv[1]
    channels = int(argv[2]) if len(argv) > 2 else 4
    n = int(argv[3]) if len(argv) > 3 else 128
    rng = random.Random(int(argv[4]) if len(argv) > 4 else 1)
    # Per channel: blobs (centre, radius, peak) in voxels.
    blobs = []
    for c in range(channels):
        mine = [((0.5 + 0.15 * math.cos(c * 1.7)) * n, (0.5 + 0.15 * math.sin(c * 1.7)) * n, 0.5 * n, 0.25 * n, 200)]
        for _ in range(6):
            mine.append((rng.uniform(0.15, 0.85) * n, rng.uniform(0.15, 0.85) * n, rng.uniform(0.2, 0.8) * n,
                         rng.uniform(0.03, 0.08) * n, rng.randint(150, 255)))
        blobs.append(mine)
    data = bytearray(n * n * n * channels)
    i = 0
    for z in range(n):
        for y in range(n):
            for x in range(n):
                for c in range(channels):
                    v = rng.randint(0, 12)  # background
                    for (bx, by, bz, r, peak) in blobs[c]:
                        d2 = ((x - bx) ** 2 + (y - by) ** 2 + (z - bz) ** 2) / (r * r)
                        if d2 < 4.0:
                            v += peak * math.exp(-2.0 * d2)
                    data[i] = min(255, int(v))
                    i += 1
    with open(out, "wb") as f:
        f.write(("NRRD0004\ntype: uint8\ndimension: 4\nsizes: %d %d %d %d\nkinds: list domain domain domain\n"
                 "spacings: nan 0.2 0.2 0.5\nencoding: raw\n\n" % (channels, n, n, n)).encode())
        f.write(bytes(data))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
