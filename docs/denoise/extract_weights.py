#!/usr/bin/env python3
"""Extracts Intel Open Image Denoise's trained weights for HDR colour from the OIDN library that
`pip install pyoidn==2.5.1.0` ships, into the resources of strahl's own denoiser.

    python3 docs/denoise/extract_weights.py [LIBRARY] [OUTDIR]

LIBRARY defaults to pyoidn's oidn/lib/libOpenImageDenoise_core.so.* (found through the installed
pyoidn package); OUTDIR to src/main/resources/dev/strahl/denoise/net.

OIDN compiles each weight file (.tza, "tensor archive") into the core library as one read-only
array, `oidn::blobs::weights::NAME`. This script
  1. scans the library for every TZA blob by its magic (0x41D7, little endian, then format
     version 2) and parses each one's tensor table (names, dimensions, layout, type, offsets);
  2. names the blobs through the library's ELF symbol table (symbol address and size = the blob's
     place and length) and checks that the name agrees with the tensors: the `rt_hdr*` networks
     are OIDN's base U-Net (enc_conv0 ... dec_conv0; `_large` variants have enc_conv1a and
     dec_conv1c, `_small` ones fewer channels) with 9 (colour, albedo, normal), 6 or 3 input
     channels and 3 output channels;
  3. writes the blobs OIDN runs at its default quality ("high": the `_large` network where one
     exists, else the base one) for HDR colour with noisy albedo and normal, with albedo, and
     alone: rt_hdr_alb_nrm.tza, rt_hdr_alb.tza, rt_hdr.tza, byte for byte, and prints their
     sizes and SHA-256 (recorded in OUTDIR/README.md);
  4. proves each file is the one OIDN runs: oidnDenoise (beside the library, in oidn/bin) denoises a
     random 56x40 image with the matching inputs once with its built-in weights and once with the
     written file (-w), and the two outputs must be the same bytes.
"""
import glob
import hashlib
import os
import struct
import subprocess
import sys
import tempfile

TZA_MAGIC = b"\xd7\x41"
WANTED = ["rt_hdr_alb_nrm", "rt_hdr_alb", "rt_hdr"]
INPUT_CHANNELS = {"rt_hdr_alb_nrm": 9, "rt_hdr_alb": 6, "rt_hdr": 3}
SYMBOL_PREFIX = "_ZN4oidn5blobs7weights"


def default_library():
    import pyoidn
    libs = glob.glob(os.path.join(os.path.dirname(pyoidn.__file__), "oidn", "lib", "libOpenImageDenoise_core.so.*"))
    if not libs:
        sys.exit("extract_weights: no libOpenImageDenoise_core.so.* in the pyoidn package")
    return sorted(libs)[-1]


def parse_tza(data, start):
    """The tensor table of the TZA blob at data[start:]: (end of the blob, [(name, dims, layout, type)])."""
    if data[start:start + 2] != TZA_MAGIC or data[start + 2] != 2:
        raise ValueError("no TZA version 2 magic")
    table = start + struct.unpack_from("<Q", data, start + 4)[0]
    count = struct.unpack_from("<I", data, table)[0]
    if count > 1000:
        raise ValueError("implausible tensor count %d" % count)
    p = table + 4
    end = p
    tensors = []
    for _ in range(count):
        (name_len,) = struct.unpack_from("<H", data, p)
        name = data[p + 2:p + 2 + name_len].decode("ascii")
        p += 2 + name_len
        ndims = data[p]
        dims = struct.unpack_from("<%dI" % ndims, data, p + 1)
        p += 1 + 4 * ndims
        layout = data[p:p + ndims].decode("ascii")
        dtype = chr(data[p + ndims])
        (offset,) = struct.unpack_from("<Q", data, p + ndims + 1)
        p += ndims + 9
        if layout not in ("x", "oihw") or dtype not in "fh":
            raise ValueError("tensor %s: layout %r type %r" % (name, layout, dtype))
        size = (2 if dtype == "h" else 4)
        for d in dims:
            size *= d
        end = max(end, start + offset + size)
        tensors.append((name, dims, layout, dtype))
    return max(end, p), tensors


def scan(data):
    """Every TZA blob in the library, by its magic: {offset: (end, tensors)}."""
    blobs = {}
    i = data.find(TZA_MAGIC)
    while i >= 0:
        try:
            blobs[i] = parse_tza(data, i)
        except (ValueError, struct.error, UnicodeDecodeError, IndexError):
            pass
        i = data.find(TZA_MAGIC, i + 1)
    return blobs


def weight_symbols(data):
    """{name: (file offset, size)} of the oidn::blobs::weights::* objects, from the ELF64 symbol table."""
    if data[:4] != b"\x7fELF" or data[4] != 2 or data[5] != 1:
        sys.exit("extract_weights: not a little-endian ELF64 library")
    shoff, = struct.unpack_from("<Q", data, 0x28)
    shentsize, shnum = struct.unpack_from("<HH", data, 0x3A)
    sections = [struct.unpack_from("<IIQQQQIIQQ", data, shoff + k * shentsize) for k in range(shnum)]
    result = {}
    for sh in sections:
        if sh[1] != 2:                              # SHT_SYMTAB
            continue
        strtab = sections[sh[6]]
        for k in range(sh[5] // sh[9]):
            st_name, _, _, st_shndx, st_value, st_size = struct.unpack_from("<IBBHQQ", data, sh[4] + k * sh[9])
            end = data.index(b"\0", strtab[4] + st_name)
            sym = data[strtab[4] + st_name:end].decode("ascii", "replace")
            if sym.startswith(SYMBOL_PREFIX) and sym.endswith("E") and 0 < st_shndx < len(sections):
                rest = sym[len(SYMBOL_PREFIX):-1]
                digits = len(rest) - len(rest.lstrip("0123456789"))
                name = rest[digits:]
                home = sections[st_shndx]
                result[name] = (st_value - home[3] + home[4], st_size)
    return result


def check(name, tensors):
    """The tensors must be OIDN's base U-Net for HDR colour with the named inputs."""
    shapes = {t[0]: t[1] for t in tensors}
    expected = ["enc_conv0", "enc_conv1", "enc_conv2", "enc_conv3", "enc_conv4", "enc_conv5a", "enc_conv5b",
                "dec_conv4a", "dec_conv4b", "dec_conv3a", "dec_conv3b", "dec_conv2a", "dec_conv2b",
                "dec_conv1a", "dec_conv1b", "dec_conv0"]
    names = sorted(shapes)
    if names != sorted([n + ".weight" for n in expected] + [n + ".bias" for n in expected]):
        sys.exit("extract_weights: %s is not OIDN's base U-Net: tensors %s" % (name, names))
    if shapes["enc_conv0.weight"][1] != INPUT_CHANNELS[name] or shapes["dec_conv0.weight"][0] != 3:
        sys.exit("extract_weights: %s has %d input and %d output channels" % (
            name, shapes["enc_conv0.weight"][1], shapes["dec_conv0.weight"][0]))


def main():
    lib = sys.argv[1] if len(sys.argv) > 1 else default_library()
    outdir = sys.argv[2] if len(sys.argv) > 2 else "src/main/resources/dev/strahl/denoise/net"
    with open(lib, "rb") as f:
        data = f.read()
    blobs = scan(data)
    symbols = weight_symbols(data)
    print("%s: %d TZA blobs, %d weight symbols" % (lib, len(blobs), len(symbols)))
    for name, (offset, size) in sorted(symbols.items(), key=lambda kv: kv[1][0]):
        end, tensors = blobs.get(offset, (None, None))
        if end is None or end - offset != size:
            sys.exit("extract_weights: symbol %s at %#x (%d bytes) is not a whole TZA blob" % (name, offset, size))
        first = dict((t[0], t[1]) for t in tensors)
        arch = "large" if "enc_conv1b.weight" in first else "base"
        print("  %-24s %#9x %8d bytes  %s, %d tensors, enc_conv0 %s" % (
            name, offset, size, arch, len(tensors), first.get("enc_conv0.weight", first.get("enc_conv1a.weight"))))
    os.makedirs(outdir, exist_ok=True)
    for name in WANTED:
        if name + "_large" in symbols:
            sys.exit("extract_weights: this OIDN has %s_large, which its default quality would run" % name)
        offset, size = symbols[name]
        check(name, blobs[offset][1])
        blob = data[offset:offset + size]
        path = os.path.join(outdir, name + ".tza")
        with open(path, "wb") as f:
            f.write(blob)
        print("wrote %s: %d bytes, sha256 %s" % (path, len(blob), hashlib.sha256(blob).hexdigest()))
    verify(lib, outdir)


def verify(lib, outdir):
    import numpy as np
    tool = os.path.join(os.path.dirname(os.path.dirname(lib)), "bin", "oidnDenoise")
    if not os.path.exists(tool):
        print("no %s: not verified against OIDN" % tool)
        return
    rng = np.random.default_rng(1)
    h, w = 40, 56
    normal = rng.normal(size=(h, w, 3))
    images = {"hdr": rng.exponential(0.5, (h, w, 3)), "alb": rng.uniform(0, 1, (h, w, 3)),
              "nrm": normal / np.linalg.norm(normal, axis=2, keepdims=True)}
    inputs = {"rt_hdr_alb_nrm": ["hdr", "alb", "nrm"], "rt_hdr_alb": ["hdr", "alb"], "rt_hdr": ["hdr"]}
    with tempfile.TemporaryDirectory() as tmp:
        for kind, a in images.items():
            with open(os.path.join(tmp, kind + ".pfm"), "wb") as f:
                f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
                a[::-1].astype("<f4").tofile(f)
        for name in WANTED:
            args = [tool, "-d", "cpu"]
            for kind in inputs[name]:
                args += ["--" + kind, os.path.join(tmp, kind + ".pfm")]
            outputs = []
            for extra in ([], ["-w", os.path.join(outdir, name + ".tza")]):
                out = os.path.join(tmp, "out%d.pfm" % len(outputs))
                subprocess.run(args + extra + ["-o", out], check=True, capture_output=True)
                with open(out, "rb") as f:
                    outputs.append(f.read())
            if outputs[0] != outputs[1]:
                sys.exit("extract_weights: OIDN's output with %s.tza differs from its built-in weights" % name)
            print("verified %s.tza: oidnDenoise gives the same bytes with it as with its built-in weights" % name)


if __name__ == "__main__":
    main()
