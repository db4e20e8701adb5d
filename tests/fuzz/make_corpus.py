#!/usr/bin/env python3
"""Writes the seed corpora of the volren fuzz targets into corpus/<format>/ (small valid
files, a few hundred bytes each). Deterministic; run from anywhere:
    python3 tests/fuzz/make_corpus.py
Detached formats hold HEADER + SEP + DATA (see FuzzSupport.h: dataSeparator)."""
import gzip
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SEP = b"\n==data==\n"


def put(fmt, name, data):
    d = os.path.join(HERE, "corpus", fmt)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def ramp(n, width=1, big=False):
    """n values 0, 7, 14, ... as unsigned ints of `width` bytes."""
    fmt = {1: "B", 2: "H", 4: "I"}[width]
    mask = (1 << (8 * width)) - 1
    return struct.pack((">" if big else "<") + fmt * n, *[(7 * i) & mask for i in range(n)])


def floats(n, big=False):
    return struct.pack((">" if big else "<") + "f" * n, *[0.25 * i - 1.0 for i in range(n)])


def gz(data):
    return gzip.compress(data, mtime=0)


# --- NIfTI-1 / NIfTI-2 ----------------------------------------------------------------------
def nifti1(dims, datatype, bitpix, data, big=False, qform=0, sform=0, vox_offset=352.0, ext=b""):
    e = ">" if big else "<"
    h = bytearray(348)
    struct.pack_into(e + "i", h, 0, 348)
    d = [len(dims)] + list(dims) + [1] * (7 - len(dims))
    struct.pack_into(e + "8h", h, 40, *d)
    struct.pack_into(e + "hh", h, 70, datatype, bitpix)
    struct.pack_into(e + "8f", h, 76, 1.0, 1.0, 1.5, 2.0, 1, 1, 1, 1)
    struct.pack_into(e + "fff", h, 108, vox_offset, 2.0 if datatype == 4 else 0.0, -5.0 if datatype == 4 else 0.0)
    struct.pack_into(e + "hh", h, 252, qform, sform)
    struct.pack_into(e + "6f", h, 256, 0.0, 0.0, 1.0, -10.0, 5.0, 2.5)
    struct.pack_into(e + "12f", h, 280, 1, 0, 0, -3, 0, 1.5, 0, 4, 0, 0, 2, 7)
    h[344:348] = b"n+1\0"
    return bytes(h) + (ext if ext else b"\0\0\0\0") + data


def nifti2(dims, datatype, bitpix, data, big=False):
    e = ">" if big else "<"
    h = bytearray(540)
    struct.pack_into(e + "i", h, 0, 540)
    h[4:12] = b"n+2\0\r\n\x1a\n"
    struct.pack_into(e + "hh", h, 12, datatype, bitpix)
    d = [len(dims)] + list(dims) + [1] * (7 - len(dims))
    struct.pack_into(e + "8q", h, 16, *d)
    struct.pack_into(e + "8d", h, 104, -1.0, 0.5, 0.5, 1.0, 1, 1, 1, 1)
    struct.pack_into(e + "q", h, 168, 544)
    struct.pack_into(e + "dd", h, 176, 1.0, 0.0)
    struct.pack_into(e + "ii", h, 344, 1, 1)
    struct.pack_into(e + "12d", h, 400, 0.5, 0, 0, 1, 0, 0.5, 0, 2, 0, 0, 1, 3)
    return bytes(h) + b"\0\0\0\0" + data


n = 4 * 3 * 2
put("nii", "uint8.nii", nifti1((4, 3, 2), 2, 8, ramp(n)))
put("nii", "int16_scaled_qform.nii", nifti1((4, 3, 2), 4, 16, ramp(n, 2), qform=1))
put("nii", "uint16_bigendian_sform.nii", nifti1((4, 3, 2), 512, 16, ramp(n, 2, True), big=True, sform=2))
put("nii", "float32_4d.nii", nifti1((2, 2, 2, 2), 16, 32, floats(16)))
put("nii", "float64.nii", nifti1((2, 2, 2), 64, 64, struct.pack("<8d", *range(8))))
put("nii", "extension.nii", nifti1((2, 2, 2), 2, 8, ramp(8), vox_offset=368.0,
                                   ext=b"\1\0\0\0" + struct.pack("<ii", 16, 0) + b"abcdefgh"))
put("nii", "nifti2_int32.nii", nifti2((3, 2, 2), 8, 32, ramp(12, 4)))
put("nii", "nifti2_bigendian_uint8.nii", nifti2((3, 2, 2), 2, 8, ramp(12), big=True))

# --- NRRD attached / detached ---------------------------------------------------------------
def nrrd(fields, data):
    return b"NRRD0004\n# volren fuzz seed\n" + "".join(f"{k}: {v}\n" for k, v in fields).encode() + b"\n" + data


base = [("type", "uint8"), ("dimension", "3"), ("sizes", "4 3 2"), ("encoding", "raw"), ("spacings", "1 1 2")]
put("nrrd", "uint8_raw.nrrd", nrrd(base, ramp(n)))
put("nrrd", "int16_big_gzip.nrrd", nrrd([("type", "short"), ("dimension", "3"), ("sizes", "4 3 2"),
                                         ("endian", "big"), ("encoding", "gzip"),
                                         ("space directions", "(1,0,0) (0,1.5,0) (0,0,2)")], gz(ramp(n, 2, True))))
put("nrrd", "rgb_4d.nrrd", nrrd([("type", "uchar"), ("dimension", "4"), ("sizes", "3 2 2 2"), ("kinds", "RGB-color domain domain domain"),
                                 ("encoding", "raw"), ("spacings", "nan 1 1 1")], ramp(24)))
put("nrrd", "float_keyvalue.nrrd", nrrd([("type", "float"), ("dimension", "3"), ("sizes", "2 2 2"), ("endian", "little"),
                                         ("encoding", "raw")], floats(8)).replace(b"type:", b"volren_rescale:=2 1\ntype:"))
put("nrrd", "uint32.nrrd", nrrd([("type", "uint"), ("dimension", "3"), ("sizes", "2 2 2"), ("endian", "little"),
                                          ("encoding", "raw")], ramp(8, 4)))

def nhdr(fields, datafile, data):
    return nrrd(fields + [("data file", datafile)], b"")[:-1] + SEP + data


put("nhdr", "uint8.nhdr", nhdr(base, "data.raw", ramp(n)))
put("nhdr", "ushort_gzip.nhdr", nhdr([("type", "ushort"), ("dimension", "3"), ("sizes", "4 3 2"), ("endian", "little"),
                                       ("encoding", "gzip")], "data.raw", gz(ramp(n, 2))))
put("nhdr", "byteskip_end.nhdr", nhdr(base + [("byte skip", "-1")], "data.raw", b"junkjunk" + ramp(n)))
put("nhdr", "lineskip.nhdr", nhdr(base + [("line skip", "2")], "data.raw", b"first line\nsecond line\n" + ramp(n)))
put("nhdr", "list.nhdr", nhdr([("type", "int8"), ("dimension", "3"), ("sizes", "4 3 1"), ("encoding", "raw")],
                              "LIST\ndata.raw", ramp(12)))
put("nhdr", "pattern.nhdr", nhdr(base, "data%d.raw 1 1 1", ramp(n)))

# --- MetaImage --------------------------------------------------------------------------------
def meta(fields, datafile):
    return "".join(f"{k} = {v}\n" for k, v in fields + [("ElementDataFile", datafile)]).encode()


mbase = [("ObjectType", "Image"), ("NDims", "3"), ("DimSize", "4 3 2"), ("ElementType", "MET_UCHAR"),
         ("ElementSpacing", "1 1 2")]
put("mha", "uchar.mha", meta(mbase, "LOCAL") + ramp(n))
comp = zlib.compress(ramp(n, 2, True))
put("mha", "short_msb_zlib.mha", meta([("ObjectType", "Image"), ("NDims", "3"), ("DimSize", "4 3 2"),
                                       ("ElementType", "MET_SHORT"), ("BinaryDataByteOrderMSB", "True"),
                                       ("CompressedData", "True"), ("CompressedDataSize", str(len(comp)))], "LOCAL") + comp)
put("mha", "float_4d_channels.mha", meta([("NDims", "4"), ("DimSize", "2 2 1 2"), ("ElementNumberOfChannels", "2"),
                                          ("ElementType", "MET_FLOAT"), ("ElementSize", "1 1 1 1")], "LOCAL") + floats(16))
put("mha", "headersize.mha", meta(mbase + [("HeaderSize", "-1")], "LOCAL") + ramp(n))
put("mhd", "uchar.mhd", meta(mbase, "data.raw") + SEP + ramp(n))
put("mhd", "ushort_zlib.mhd", meta([("NDims", "3"), ("DimSize", "4 3 2"), ("ElementType", "MET_USHORT"),
                                    ("CompressedData", "True")], "data.raw") + SEP + zlib.compress(ramp(n, 2)))
put("mhd", "headersize.mhd", meta(mbase + [("HeaderSize", "4")], "data.raw") + SEP + b"HEAD" + ramp(n))
put("mhd", "list.mhd", meta([("NDims", "3"), ("DimSize", "4 3 1"), ("ElementType", "MET_CHAR")], "LIST\ndata.raw") + SEP + ramp(12))
put("mhd", "uint_pattern.mhd", meta([("NDims", "3"), ("DimSize", "2 2 2"), ("ElementType", "MET_UINT")],
                                    "data%d.raw 1 1 1") + SEP + ramp(8, 4))

# --- raw + sidecar, QVis .dat -------------------------------------------------------------------
put("raw", "uint8.raw", b"dims=4,3,2 type=uint8\n" + SEP + ramp(n))
put("raw", "uint16_big_spacing.raw", b"# comment\ndims=4,3,2\ntype=uint16 endian=big spacing=1,1,2.5\n" + SEP + ramp(n, 2, True))
put("raw", "gzip_channels.raw", b"dims=2,2,2 type=uint8 channels=3 encoding=gzip\n" + SEP + gz(ramp(24)))
put("raw", "skip_float.raw", b"dims=2,2,2 type=float32 skip=6\n" + SEP + b"HEADER" + floats(8))
put("raw", "skip_end_int32.raw", b"dims=2,2,2 type=int32 skip=-1\n" + SEP + b"xx" + ramp(8, 4))
put("dat", "uchar.dat", b"ObjectFileName: data.raw\nResolution: 4 3 2\nSliceThickness: 1 1 1.5\nFormat: UCHAR\n" + SEP + ramp(n))
put("dat", "ushort.dat", b"ObjectFileName:\tdata.raw\r\nTaggedFileName: ---\r\nResolution:\t4 3 2\r\nSliceThickness:\t0.5 0.5 1\r\n"
                         b"Format:\tUSHORT\r\nNbrTags:\t0\r\nObjectType:\tTEXTURE_VOLUME_OBJECT\r\nObjectModel:\tI\r\n"
                         b"GridType:\tEQUIDISTANT\r\n" + SEP + ramp(n, 2))
put("dat", "float_rgba.dat", b"ObjectFileName: data.raw\nResolution: 2 2 2\nSliceThickness: 1 1 1\nFormat: FLOAT\n"
                             b"ObjectModel: RGBA\n" + SEP + floats(32))

# --- TIFF (baseline, strips; written by hand: no third-party modules needed) ----------------
def tiff(pages, width, height, bits, sample_format=1, big=False, description=None, rows_per_strip=None):
    """Multi-page grey TIFF; pages = list of bytes (already in file byte order)."""
    e = ">" if big else "<"
    out = bytearray(b"MM\0*" if big else b"II*\0") + struct.pack(e + "I", 0)
    first_ifd_at = 4
    prev_link = first_ifd_at
    rps = rows_per_strip or height
    for k, pixels in enumerate(pages):
        row_bytes = width * bits // 8
        strips = [pixels[r * row_bytes:(r + rps) * row_bytes] for r in range(0, height, rps)]
        offsets = []
        for s in strips:
            offsets.append(len(out))
            out += s
        if len(out) % 2:
            out += b"\0"
        extra = {}
        def blob(data):
            if len(out) % 2:
                out.extend(b"\0")
            at = len(out)
            out.extend(data)
            return at
        desc = description.encode() + b"\0" if (description and k == 0) else None
        desc_at = blob(desc) if desc and len(desc) > 4 else None
        so_at = blob(struct.pack(e + "I" * len(offsets), *offsets)) if len(offsets) > 1 else None
        sc_at = blob(struct.pack(e + "I" * len(strips), *[len(s) for s in strips])) if len(strips) > 1 else None
        res_at = blob(struct.pack(e + "II", 2, 1))  # 2 pixels per unit = 0.5 units spacing
        entries = [(256, 3, 1, width), (257, 3, 1, height), (258, 3, 1, bits), (259, 3, 1, 1), (262, 3, 1, 1)]
        if desc:
            entries.append((270, 2, len(desc), desc_at))
        entries.append((273, 4, len(offsets), so_at if so_at is not None else offsets[0]))
        entries += [(277, 3, 1, 1), (278, 3, 1, rps)]
        entries.append((279, 4, len(strips), sc_at if sc_at is not None else len(strips[0])))
        entries += [(282, 5, 1, res_at), (283, 5, 1, res_at), (296, 3, 1, 3), (339, 3, 1, sample_format)]
        if len(out) % 2:
            out += b"\0"
        ifd_at = len(out)
        struct.pack_into(e + "I", out, prev_link, ifd_at)
        out += struct.pack(e + "H", len(entries))
        for tag, typ, count, value in entries:
            if typ == 3 and count == 1:
                out += struct.pack(e + "HHI", tag, typ, count) + struct.pack(e + "HH", value, 0)
            else:
                out += struct.pack(e + "HHII", tag, typ, count, value)
        prev_link = len(out)
        out += struct.pack(e + "I", 0)
    return bytes(out)


w, h = 4, 3
put("tif", "uint8_3pages.tif", tiff([ramp(12)] * 3, w, h, 8))
put("tif", "uint16_imagej.tif", tiff([ramp(12, 2), ramp(12, 2)[::-1]], w, h, 16,
                                     description="ImageJ=1.53t\nimages=2\nslices=2\nunit=micron\nspacing=2.5\n"))
put("tif", "float_bigendian_strips.tif", tiff([floats(12, True)] * 2, w, h, 32, sample_format=3, big=True, rows_per_strip=1))
put("tif", "int16_imagej_channels.tif", tiff([ramp(12, 2)] * 4, w, h, 16, sample_format=2,
                                             description="ImageJ=1.53t\nimages=4\nchannels=2\nslices=2\nhyperstack=true\n"))
ome = ('<?xml version="1.0" encoding="UTF-8"?><OME xmlns="http://www.openmicroscopy.org/Schemas/OME/2016-06">'
       '<Image ID="Image:0"><Pixels ID="Pixels:0" DimensionOrder="XYZCT" Type="uint8" SizeX="4" SizeY="3" SizeZ="2" '
       'SizeC="1" SizeT="1" PhysicalSizeX="0.5" PhysicalSizeY="0.5" PhysicalSizeZ="2"><TiffData/></Pixels></Image></OME>')
put("tif", "ome.tif", tiff([ramp(12)] * 2, w, h, 8, description=ome))

# --- DICOM (explicit VR little endian, one CT-like slice) -------------------------------------
def element(group, elem, vr, value):
    if isinstance(value, str):
        value = value.encode()
        if len(value) % 2:
            value += b"\0" if vr == "UI" else b" "
    if vr in ("OB", "OW", "OF", "SQ", "UT", "UN"):
        return struct.pack("<HH", group, elem) + vr.encode() + b"\0\0" + struct.pack("<I", len(value)) + value
    return struct.pack("<HH", group, elem) + vr.encode() + struct.pack("<H", len(value)) + value


def us(v):
    return struct.pack("<H", v)


def dicom(rows, cols, bits, signed, pixels, extra=()):
    sop = "1.2.840.10008.5.1.4.1.1.2"
    inst = "1.2.826.0.1.3680043.2.1125.1.1"
    meta = (element(2, 1, "OB", b"\0\1") + element(2, 2, "UI", sop) + element(2, 3, "UI", inst) +
            element(2, 0x10, "UI", "1.2.840.10008.1.2.1"))
    meta = element(2, 0, "UL", struct.pack("<I", len(meta))) + meta
    ds = [element(8, 0x16, "UI", sop), element(8, 0x18, "UI", inst), element(8, 0x60, "CS", "CT"),
          element(0x20, 0xD, "UI", "1.2.826.0.1.3680043.2.1125.1.2"), element(0x20, 0xE, "UI", "1.2.826.0.1.3680043.2.1125.1.3"),
          element(0x20, 0x13, "IS", "1"), element(0x20, 0x32, "DS", "-10\\-20\\5"), element(0x20, 0x37, "DS", "1\\0\\0\\0\\1\\0"),
          element(0x28, 2, "US", us(1)), element(0x28, 4, "CS", "MONOCHROME2"), element(0x28, 0x10, "US", us(rows)),
          element(0x28, 0x11, "US", us(cols)), element(0x28, 0x30, "DS", "0.5\\0.75"),
          element(0x28, 0x100, "US", us(bits)), element(0x28, 0x101, "US", us(bits)), element(0x28, 0x102, "US", us(bits - 1)),
          element(0x28, 0x103, "US", us(1 if signed else 0))] + list(extra)
    ds.append(element(0x7FE0, 0x10, "OW" if bits > 8 else "OB", pixels))
    ds.sort(key=lambda e: struct.unpack("<HH", e[:4]))  # ascending tags, as DICOM requires
    return b"\0" * 128 + b"DICM" + meta + b"".join(ds)


put("dcm", "ct_int16.dcm", dicom(3, 4, 16, True, ramp(12, 2),
                                 [element(0x18, 0x50, "DS", "2"), element(0x28, 0x1052, "DS", "-1024"), element(0x28, 0x1053, "DS", "1")]))
put("dcm", "uint8.dcm", dicom(3, 4, 8, False, ramp(12)))
put("dcm", "uint16_thickness.dcm", dicom(2, 2, 16, False, ramp(4, 2), [element(0x18, 0x50, "DS", "1.5")]))

# --- PVM ----------------------------------------------------------------------------------------
put("pvm", "pvm1.pvm", b"PVM\n4 3 2\n1\n" + ramp(n))
put("pvm", "pvm1_comment.pvm", b"PVM\n# comment\n2 2 2\n2\n" + ramp(8, 2, True))
put("pvm", "pvm2.pvm", b"PVM2\n4 3 2\n1 1 2\n2\n" + ramp(n, 2, True))
put("pvm", "pvm3_strings.pvm", b"PVM3\r\n2 2 2\r\n0.5 0.5 1\r\n1\r\n" + ramp(8) + b"description\0courtesy\0params\0comment\0")
put("pvm", "dds.pvm", b"DDS v3d\n" + ramp(16))

# --- OME-Zarr: ZARRAY + SEP + ZATTRS + SEP + CHUNK (chunk 0 of level 0; FuzzZarr.cpp) -----------
# Blosc seeds with real lz4/zstd streams need numcodecs: tests/io/data/make_omezarr_fixtures.py
# writes those (corpus/zarr/blosc-*.seed).



def zarray(shape, chunks, dtype, compressor=None, order="C", fill=0, sep="."):
    return json.dumps({"zarr_format": 2, "shape": shape, "chunks": chunks, "dtype": dtype, "compressor": compressor,
                       "fill_value": fill, "order": order, "filters": None, "dimension_separator": sep}).encode()


def zattrs(names, scale, omero=None):
    kinds = {"t": "time", "c": "channel", "z": "space", "y": "space", "x": "space"}
    a = {"multiscales": [{"version": "0.4", "axes": [{"name": n, "type": kinds[n], "unit": "micrometer" if kinds[n] == "space" else None}
                                                     for n in names],
                          "datasets": [{"path": "0", "coordinateTransformations": [{"type": "scale", "scale": scale},
                                                                                   {"type": "translation", "translation": [0.0] * len(names)}]}]}]}
    if omero:
        a["omero"] = omero
    return json.dumps(a).encode()


def blosc_memcpy(data, typesize):
    """A blosc 1 frame that stores `data` uncompressed (flag 0x02), as blosc does for small buffers."""
    return struct.pack("<BBBBIII", 2, 1, 0x02 | 0x01, typesize, len(data), len(data), len(data) + 16) + data


zyx = zattrs("zyx", [2.0, 0.5, 0.5])
put("zarr", "zlib_u2_dot.seed", zarray([2, 3, 4], [2, 3, 4], "<u2", {"id": "zlib", "level": 1}) + SEP + zyx + SEP +
    zlib.compress(ramp(24, 2)))
put("zarr", "raw_big_i2_forder_slash.seed", zarray([2, 3, 5], [2, 3, 4], ">i2", None, order="F", sep="/") + SEP + zyx + SEP +
    ramp(24, 2, True))
put("zarr", "gzip_f4_nan.seed", zarray([2, 2, 3], [2, 2, 2], "<f4", {"id": "gzip", "level": 1}, fill="NaN") + SEP + zyx + SEP +
    gz(floats(8)))
put("zarr", "blosc_memcpy_tczyx.seed", zarray([2, 2, 2, 2, 3], [1, 1, 2, 2, 3], "|u1", {"id": "blosc", "cname": "lz4", "clevel": 5,
                                                                                        "shuffle": 1, "blocksize": 0}, sep="/") +
    SEP + zattrs("tczyx", [1.0, 1.0, 2.0, 0.5, 0.5], {"channels": [{"label": "a", "color": "FF0000", "window": {"min": 0, "max": 255,
                                                                                                             "start": 0, "end": 200}},
                                                                   {"label": "b", "color": "00ff00", "active": False}]}) +
    SEP + blosc_memcpy(ramp(12), 1))
put("zarr", "f8_yx.seed", zarray([3, 4], [3, 4], "<f8", None) + SEP + zattrs("yx", [0.5, 0.5]) + SEP + struct.pack("<12d", *range(12)))
