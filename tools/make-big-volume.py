#!/usr/bin/python3
"""Writes a synthetic 16-bit volume larger than RAM, for testing volumes opened lazily (the
readers' `lazy` / `ramBudgetMB=N` options) and the bricked renderer.

Usage: tools/make-big-volume.py OUT [--dims X Y Z] [--spacing X Y Z]
  OUT ending in .nhdr: a detached NRRD header OUT plus its voxels in OUT with .raw instead
       (the .raw can also be read alone: dims=X,Y,Z type=uint16);
  OUT ending in .nrrd: one attached NRRD file (header, blank line, voxels).
  --dims     voxels along x, y, z (default 2048 2048 1024: 8 GiB)
  --spacing  voxel size (default 1 1 1)

Voxels: uint16, little endian, encoding raw, x fastest. The field is smooth and closed-form,
with structure at several scales so that bricks at every level differ: nested spherical shells
(about 12 across the box), a few Gaussian blobs of radii from 1/4 to 1/50 of the box, and a
gyroid band (period 1/8 of the box); values 0..60000. It is written slab by slab (about
16 MiB of float32 voxels at a time, at least one slice): memory stays near ten such arrays
(under 200 MiB at 2048 x 2048) whatever the depth. Progress goes to stderr. Needs python3
and numpy only (Debian: python3-numpy).
"""
import argparse
import os
import sys
import time

import numpy as np

BLOBS = [  # centre (u, v, w in [0, 1]), radius (sigma), weight
    ((0.30, 0.35, 0.40), 0.25, 0.6),
    ((0.70, 0.60, 0.55), 0.10, 0.9),
    ((0.55, 0.25, 0.70), 0.05, 1.0),
    ((0.20, 0.75, 0.30), 0.02, 1.0),
    ((0.80, 0.20, 0.20), 0.03, 0.8),
]


def field(u, v, w):
    """Values in [0, 1] at normalised coordinates (broadcast arrays, float32)."""
    r = np.sqrt((u - 0.5) ** 2 + (v - 0.5) ** 2 + (w - 0.5) ** 2)
    shells = (0.5 + 0.5 * np.cos(2 * np.pi * 12 * r)) * np.exp(-((r / 0.45) ** 8))
    blobs = np.zeros(np.broadcast_shapes(u.shape, v.shape, w.shape), dtype=np.float32)
    for (cu, cv, cw), sigma, weight in BLOBS:
        d2 = (u - cu) ** 2 + (v - cv) ** 2 + (w - cw) ** 2
        blobs += np.float32(weight) * np.exp(-d2 / np.float32(2 * sigma * sigma))
    k = np.float32(2 * np.pi * 8)
    g = np.sin(k * u) * np.cos(k * v) + np.sin(k * v) * np.cos(k * w) + np.sin(k * w) * np.cos(k * u)
    band = np.exp(-((g / np.float32(0.3)) ** 2))
    return np.clip(0.35 * shells + 0.4 * np.minimum(blobs, 1) + 0.25 * band, 0, 1)


def header(dims, spacing, data_file):
    lines = ["NRRD0004", "# volren tools/make-big-volume.py: synthetic shells, blobs and a gyroid band",
             "type: uint16", "dimension: 3", "sizes: %d %d %d" % dims, "spacings: %g %g %g" % spacing,
             "endian: little", "encoding: raw"]
    if data_file:
        lines.append("data file: " + data_file)
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out")
    parser.add_argument("--dims", type=int, nargs=3, default=[2048, 2048, 1024], metavar=("X", "Y", "Z"))
    parser.add_argument("--spacing", type=float, nargs=3, default=[1.0, 1.0, 1.0], metavar=("X", "Y", "Z"))
    args = parser.parse_args()
    nx, ny, nz = args.dims
    if min(args.dims) < 1:
        parser.error("dims must be positive")
    if args.out.endswith(".nhdr"):
        raw = args.out[:-5] + ".raw"
        with open(args.out, "w") as f:
            f.write(header((nx, ny, nz), tuple(args.spacing), os.path.basename(raw)))
        out = open(raw, "wb")
    elif args.out.endswith(".nrrd"):
        out = open(args.out, "wb")
        out.write((header((nx, ny, nz), tuple(args.spacing), None) + "\n").encode())
    else:
        parser.error("OUT must end in .nhdr (detached) or .nrrd (attached)")

    u = ((np.arange(nx, dtype=np.float32) + 0.5) / nx)[None, None, :]
    v = ((np.arange(ny, dtype=np.float32) + 0.5) / ny)[None, :, None]
    slab = max(1, min(nz, (16 << 20) // (nx * ny * 4)))  # slices per step: ~16 MiB of float32
    total = nx * ny * nz * 2
    start = time.time()
    with out:
        for z0 in range(0, nz, slab):
            n = min(slab, nz - z0)
            w = ((np.arange(z0, z0 + n, dtype=np.float32) + 0.5) / nz)[:, None, None]
            values = np.rint(field(u, v, w) * 60000).astype("<u2")
            values.tofile(out)
            done = (z0 + n) * nx * ny * 2
            elapsed = time.time() - start
            rate = done / elapsed if elapsed > 0 else 0
            eta = (total - done) / rate if rate > 0 else 0
            sys.stderr.write("\r%s: %5.1f%%  %d of %d slices  %.0f MiB/s  %.0f s left   "
                             % (args.out, 100.0 * done / total, z0 + n, nz, rate / 2**20, eta))
            sys.stderr.flush()
    sys.stderr.write("\n")


if __name__ == "__main__":
    main()
