#!/usr/bin/env python3
"""Adds Gaussian noise to an 8-bit NIfTI-1 volume (.nii or .nii.gz), for measuring lit accuracy
on noisy data (issue 16, point 5): bone in noisy soft tissue, as real low-dose CTs look.

Usage: tools/make-noisy-volume.py IN.nii[.gz] OUT.nii[.gz] [SIGMA] [SEED]
SIGMA is in grey levels (default 6), SEED makes the noise repeatable (default 1). The header is
kept; values are rounded and clamped to 0..255. Pure Python (no numpy): ~15 s for 256^3.
"""
import gzip
import random
import struct
import sys


def read(path):
    with open(path, "rb") as f:
        data = f.read()
    return gzip.decompress(data) if path.endswith(".gz") else data


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    src, dst = argv[1], argv[2]
    sigma = float(argv[3]) if len(argv) > 3 else 6.0
    seed = int(argv[4]) if len(argv) > 4 else 1
    raw = read(src)
    if len(raw) < 352 or struct.unpack("<i", raw[:4])[0] != 348:
        sys.stderr.write(f"{src}: not a little-endian NIfTI-1 file\n")
        return 1
    datatype = struct.unpack("<h", raw[70:72])[0]
    if datatype != 2:  # DT_UNSIGNED_CHAR
        sys.stderr.write(f"{src}: voxel type {datatype} is not uint8 (2)\n")
        return 1
    offset = int(struct.unpack("<f", raw[108:112])[0])
    voxels = bytearray(raw[offset:])
    rng = random.Random(seed)
    gauss = rng.gauss
    for i, v in enumerate(voxels):
        voxels[i] = min(255, max(0, int(round(v + gauss(0.0, sigma)))))
    out = raw[:offset] + bytes(voxels)
    if dst.endswith(".gz"):
        out = gzip.compress(out, 6)
    with open(dst, "wb") as f:
        f.write(out)
    print(f"{dst}: {len(voxels)} voxels, Gaussian noise sigma {sigma} grey levels, seed {seed}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
