#!/usr/bin/python3
"""Writes the OME-Zarr 0.4 (zarr v2) fixtures of tests/io/OmeZarrReaderTest.cpp into
tests/io/data/omezarr/ with zarr-python, independently of volren's reader and writer.

Made with Debian 12's python3-zarr 2.13.6, python3-numcodecs 0.11.0 and numpy 1.24.2
(`apt-get install python3-zarr`); Debian's python3 is /usr/bin/python3 (a pyenv python3 first
on PATH does not see the Debian modules). Rerun after changing it:
    /usr/bin/python3 tests/io/data/make_omezarr_fixtures.py

Every array holds a closed formula of its indices, written next to it below and repeated in
the test, so the test checks voxel values against the formula, not against this script's
output. Each fixture is a few KB. The output is the same from run to run except the gzip
chunks of gzip_u1.ome.zarr, whose gzip headers carry the time of writing.

It also writes the fuzz seeds whose chunks are compressed blosc streams,
tests/fuzz/corpus/zarr/blosc-*.seed (make_corpus.py, standard library only, cannot)."""
import json
import os
import shutil

import numcodecs
import numpy as np
import zarr

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "omezarr")
FUZZ_CORPUS = os.path.join(HERE, "..", "..", "fuzz", "corpus", "zarr")
SEP = b"\n==data==\n"  # tests/fuzz/FuzzSupport.h: dataSeparator

BLOSC_LZ4 = numcodecs.Blosc(cname="lz4", clevel=5, shuffle=numcodecs.Blosc.SHUFFLE)
BLOSC_ZSTD_BIT = numcodecs.Blosc(cname="zstd", clevel=3, shuffle=numcodecs.Blosc.BITSHUFFLE)


def grid(shape):
    """Index arrays (one per dimension, slowest first) of an array of `shape`."""
    return np.indices(shape)


def axes(names, units=None):
    kinds = {"t": "time", "c": "channel", "z": "space", "y": "space", "x": "space"}
    out = []
    for n in names:
        a = {"name": n, "type": kinds[n]}
        if units and n in units:
            a["unit"] = units[n]
        out.append(a)
    return out


def image(name, levels, axis_names, scales, units=None, translations=None, omero=None,
          separator="/", compressor=BLOSC_LZ4, chunks=None, order="C", fill_value=0):
    """An OME-Zarr 0.4 image group `name` with one array per entry of `levels`."""
    path = os.path.join(OUT, name)
    shutil.rmtree(path, ignore_errors=True)
    group = zarr.open_group(path, mode="w")
    datasets = []
    for i, data in enumerate(levels):
        group.create_dataset(str(i), data=data, chunks=chunks[i] if chunks else True, compressor=compressor,
                             dimension_separator=separator, order=order, fill_value=fill_value)
        transforms = [{"type": "scale", "scale": scales[i]}]
        if translations:
            transforms.append({"type": "translation", "translation": translations[i]})
        datasets.append({"path": str(i), "coordinateTransformations": transforms})
    group.attrs["multiscales"] = [{"version": "0.4", "name": name, "axes": axes(axis_names, units),
                                   "datasets": datasets}]
    if omero:
        group.attrs["omero"] = omero
    return path


def main():
    os.makedirs(OUT, exist_ok=True)

    # blosc_lz4.ome.zarr: <u2, z,y,x = 5,6,7, chunks 2,3,4 (edge chunks padded), blosc lz4 +
    # byte shuffle, "/" separator. v = x + 10*y + 100*z.
    z, y, x = grid((5, 6, 7))
    image("blosc_lz4.ome.zarr", [(x + 10 * y + 100 * z).astype("<u2")], "zyx", [[1.0, 1.0, 1.0]],
          chunks=[(2, 3, 4)])

    # zlib_dot.ome.zarr: <i2, 4,5,6, chunks 3,3,3, zlib, "." separator. v = x - 2*y + 3*z - 20.
    z, y, x = grid((4, 5, 6))
    image("zlib_dot.ome.zarr", [(x - 2 * y + 3 * z - 20).astype("<i2")], "zyx", [[1.0, 1.0, 1.0]],
          chunks=[(3, 3, 3)], separator=".", compressor=numcodecs.Zlib(level=6))

    # gzip_u1.ome.zarr: |u1, 3,4,5, chunks 2,2,2, gzip, "/". v = (x*7 + y*3 + z*11) % 256.
    z, y, x = grid((3, 4, 5))
    image("gzip_u1.ome.zarr", [((x * 7 + y * 3 + z * 11) % 256).astype("|u1")], "zyx", [[1.0, 1.0, 1.0]],
          chunks=[(2, 2, 2)], compressor=numcodecs.GZip(level=5))

    # raw_bigendian.ome.zarr: >u2, uncompressed, ".", 3,4,5, chunks 2,2,5.
    # v = 1000*z + 37*x + 5*y + 256 (high and low bytes differ, so a missed swap shows).
    z, y, x = grid((3, 4, 5))
    image("raw_bigendian.ome.zarr", [(1000 * z + 37 * x + 5 * y + 256).astype(">u2")], "zyx",
          [[1.0, 1.0, 1.0]], chunks=[(2, 2, 5)], separator=".", compressor=None)

    # f8_converted.ome.zarr: >f8 (read as float32), zlib, "/", 3,3,4, chunks 2,2,2.
    # v = 0.5*x + 0.25*y - z.
    z, y, x = grid((3, 3, 4))
    image("f8_converted.ome.zarr", [(0.5 * x + 0.25 * y - z).astype(">f8")], "zyx", [[1.0, 1.0, 1.0]],
          chunks=[(2, 2, 2)], compressor=numcodecs.Zlib(level=1))

    # i4_converted.ome.zarr: <i4 (read as float32), blosc lz4, ".", 2,3,4, chunks 2,3,4.
    # v = 100000*z - 1000*y + x.
    z, y, x = grid((2, 3, 4))
    image("i4_converted.ome.zarr", [(100000 * z - 1000 * y + x).astype("<i4")], "zyx", [[1.0, 1.0, 1.0]],
          chunks=[(2, 3, 4)], separator=".")

    # float_nan_missing.ome.zarr: <f4, fill_value NaN, blosc zstd + bitshuffle, "/", 4,4,4, chunks
    # 2,2,2; the chunk file 0/1/0 (z 0-1, y 2-3, x 0-1) is deleted. v = 0.25*x - y + 0.5*z elsewhere.
    z, y, x = grid((4, 4, 4))
    path = image("float_nan_missing.ome.zarr", [(0.25 * x - y + 0.5 * z).astype("<f4")], "zyx",
                 [[1.0, 1.0, 1.0]], chunks=[(2, 2, 2)], compressor=BLOSC_ZSTD_BIT, fill_value=float("nan"))
    os.remove(os.path.join(path, "0", "0", "1", "0"))

    # pyramid.ome.zarr: |u1, 2 levels, level 0 z,y,x = 6,8,10 with v = (x + 2*y + 3*z) % 256,
    # level 1 = level 0[::2, ::2, ::2] (3,4,5), blosc lz4, "/", chunks 4,4,4 and 2,2,2.
    # Scales (z,y,x): level 0 [2.0, 0.5, 0.25], level 1 [4.0, 1.0, 0.5]; translations level 0
    # zeros, level 1 [1.0, 0.25, 0.125]; units micrometer.
    z, y, x = grid((6, 8, 10))
    level0 = ((x + 2 * y + 3 * z) % 256).astype("|u1")
    image("pyramid.ome.zarr", [level0, np.ascontiguousarray(level0[::2, ::2, ::2])], "zyx",
          [[2.0, 0.5, 0.25], [4.0, 1.0, 0.5]], units={"z": "micrometer", "y": "micrometer", "x": "micrometer"},
          translations=[[0.0, 0.0, 0.0], [1.0, 0.25, 0.125]], chunks=[(4, 4, 4), (2, 2, 2)])

    # tczyx.ome.zarr: <u2, t,c,z,y,x = 2,2,3,4,5, chunks 1,1,2,2,5, blosc lz4, "/".
    # v = 1000*t + 100*c + 20*z + 5*y + x. Scales [0.5, 1, 1.5, 0.25, 0.25]; units t second,
    # z/y/x micrometer. omero: channel 0 "DAPI" colour 0000FF window 0..4095 start 10 end 900,
    # channel 1 "GFP" colour 00FF00 window 0..65535 start 100 end 2000, inactive.
    t, c, z, y, x = grid((2, 2, 3, 4, 5))
    omero = {"channels": [
        {"label": "DAPI", "color": "0000FF", "active": True,
         "window": {"min": 0, "max": 4095, "start": 10, "end": 900}},
        {"label": "GFP", "color": "00FF00", "active": False,
         "window": {"min": 0, "max": 65535, "start": 100, "end": 2000}}],
        "rdefs": {"model": "color"}}
    image("tczyx.ome.zarr", [(1000 * t + 100 * c + 20 * z + 5 * y + x).astype("<u2")], "tczyx",
          [[0.5, 1.0, 1.5, 0.25, 0.25]], units={"t": "second", "z": "micrometer", "y": "micrometer", "x": "micrometer"},
          omero=omero, chunks=[(1, 1, 2, 2, 5)])

    # forder.ome.zarr: |i1, order F, zlib, ".", 4,5,6, chunks 3,4,5. v = x - 2*y + 3*z - 5.
    z, y, x = grid((4, 5, 6))
    image("forder.ome.zarr", [(x - 2 * y + 3 * z - 5).astype("|i1")], "zyx", [[1.0, 1.0, 1.0]],
          chunks=[(3, 4, 5)], separator=".", compressor=numcodecs.Zlib(level=6), order="F")

    fuzz_seeds()


def fuzz_seeds():
    """Seeds of fuzz_zarr (tests/fuzz/FuzzZarr.cpp) whose chunk is a real compressed blosc
    stream (blosc copies buffers under 128 bytes uncompressed): ZARRAY + SEP + ZATTRS + SEP + CHUNK."""
    os.makedirs(FUZZ_CORPUS, exist_ok=True)
    attrs = json.dumps({"multiscales": [{"version": "0.4", "axes": axes("zyx"), "datasets": [
        {"path": "0", "coordinateTransformations": [{"type": "scale", "scale": [1.0, 1.0, 1.0]}]}]}]}).encode()
    z, y, x = grid((4, 8, 8))
    for name, dtype, codec in (("blosc-lz4-u2.seed", "<u2", BLOSC_LZ4), ("blosc-zstd-bitshuffle-f4.seed", "<f4", BLOSC_ZSTD_BIT)):
        data = ((x + y * 3 + z * 5) % 7).astype(dtype)
        meta = {"zarr_format": 2, "shape": [4, 8, 8], "chunks": [4, 8, 8], "dtype": dtype, "compressor": codec.get_config(),
                "fill_value": 0, "order": "C", "filters": None, "dimension_separator": "/"}
        with open(os.path.join(FUZZ_CORPUS, name), "wb") as f:
            f.write(json.dumps(meta).encode() + SEP + attrs + SEP + codec.encode(data))


if __name__ == "__main__":
    main()
