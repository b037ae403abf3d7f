#!/usr/bin/env python3
"""bench/bsp_stats.py: counts read straight from a compiled BSP, for bench/compile_bench.sh.

    bench/bsp_stats.py file.bsp [file.bsp ...]      one JSON object per line

Reads BSP29, BSP2 and 2PSB (RMQ) files. Written for Starbow from the public layout of the
format; it depends on nothing but the Python standard library.

Fields:
  format                  "BSP29", "BSP2" or "2PSB"
  faces, leafs, nodes, clipnodes, marksurfaces, models
                          element counts of those lumps (leafs includes leaf 0, the shared
                          solid leaf; that is how the header counts them)
  visleafs                model 0's count of leaves that carry a PVS row (leaves 1..visleafs)
  visdata_bytes           size of the visibility lump
  vis_leaves              mean, over leaves 1..visleafs, of the number of leaves set in the
                          leaf's PVS row (a leaf with no row, visofs < 0, sees every leaf)
  vis_faces               mean, over the same leaves, of the sum of nummarksurfaces of every
                          leaf in its PVS (render work per view, as ../shared/quake/REFERENCE.md
                          defines it)
"""
import json
import struct
import sys

LUMP_ENTITIES, LUMP_PLANES, LUMP_TEXTURES, LUMP_VERTEXES, LUMP_VISIBILITY, LUMP_NODES, \
    LUMP_TEXINFO, LUMP_FACES, LUMP_LIGHTING, LUMP_CLIPNODES, LUMP_LEAFS, LUMP_MARKSURFACES, \
    LUMP_EDGES, LUMP_SURFEDGES, LUMP_MODELS = range(15)

# Per format: element sizes of the lumps counted here, and how to read a leaf's
# (visofs, nummarksurfaces).
FORMATS = {
    # name: (face, leaf, node, clipnode, marksurface, leaf unpack, visofs idx, nummark idx)
    "BSP29": (20, 28, 24, 8, 2, "<ii6hHH4B", 1, 9),
    "BSP2": (28, 44, 44, 12, 4, "<ii6fII4B", 1, 9),
    "2PSB": (28, 32, 32, 12, 4, "<ii6hII4B", 1, 9),
}
MODEL_SIZE = 64  # 9 floats, 4 headnodes, visleafs, firstface, numfaces


def popcount(b):
    return bin(b).count("1")


POP = [popcount(i) for i in range(256)]


def decompress_row(vis, ofs, row_bytes):
    """The PVS row at vis[ofs:], zero runs expanded; returns a bytes object of row_bytes."""
    out = bytearray()
    i = ofs
    n = len(vis)
    while len(out) < row_bytes:
        if i >= n:
            raise ValueError("visdata row at %d runs past the lump end" % ofs)
        c = vis[i]
        i += 1
        if c:
            out.append(c)
        else:
            if i >= n:
                raise ValueError("visdata row at %d: zero run without a count" % ofs)
            out.extend(b"\0" * vis[i])
            i += 1
    return bytes(out[:row_bytes])


def stats(path):
    with open(path, "rb") as f:
        data = f.read()
    magic = data[:4]
    if magic == b"BSP2":
        fmt = "BSP2"
    elif magic == b"2PSB":
        fmt = "2PSB"
    elif struct.unpack_from("<i", data, 0)[0] == 29:
        fmt = "BSP29"
    else:
        raise ValueError("%s: not a BSP29/BSP2/2PSB file (magic %r)" % (path, magic))
    lumps = [struct.unpack_from("<ii", data, 4 + 8 * i) for i in range(15)]

    def lump(i):
        ofs, ln = lumps[i]
        if ofs < 0 or ln < 0 or ofs + ln > len(data):
            raise ValueError("%s: lump %d (offset %d, length %d) outside the file" % (path, i, ofs, ln))
        return data[ofs:ofs + ln]

    face_sz, leaf_sz, node_sz, clip_sz, mark_sz, leaf_fmt, vis_i, mark_i = FORMATS[fmt]
    leaf_lump = lump(LUMP_LEAFS)
    models = lump(LUMP_MODELS)
    vis = lump(LUMP_VISIBILITY)
    nleafs = len(leaf_lump) // leaf_sz
    visleafs = struct.unpack_from("<i", models, 52)[0] if len(models) >= MODEL_SIZE else 0
    visleafs = max(0, min(visleafs, nleafs - 1))
    leaves = [struct.unpack_from(leaf_fmt, leaf_lump, i * leaf_sz) for i in range(nleafs)]
    marks = [lf[mark_i] for lf in leaves]

    row_bytes = (visleafs + 7) // 8
    # Per byte k of a row and byte value v: leaves set and their marksurfaces summed.
    mark_of_bit = [marks[j + 1] if j < visleafs else 0 for j in range(row_bytes * 8)]
    byte_faces = []
    for k in range(row_bytes):
        t = [0] * 256
        for v in range(1, 256):
            low = (v & -v).bit_length() - 1
            t[v] = t[v & (v - 1)] + mark_of_bit[k * 8 + low]
        byte_faces.append(t)
    all_row = bytes([0xff] * row_bytes)
    if visleafs & 7:
        all_row = all_row[:-1] + bytes([(1 << (visleafs & 7)) - 1])
    total_leaves = 0
    total_faces = 0
    for li in range(1, visleafs + 1):
        visofs = leaves[li][vis_i]
        row = all_row if (visofs < 0 or not vis) else decompress_row(vis, visofs, row_bytes)
        if visleafs & 7:  # bits past the last leaf are padding
            row = row[:-1] + bytes([row[-1] & ((1 << (visleafs & 7)) - 1)])
        total_leaves += sum(POP[b] for b in row)
        total_faces += sum(t[b] for t, b in zip(byte_faces, row))
    n = max(visleafs, 1)
    return {
        "path": path,
        "format": fmt,
        "faces": len(lump(LUMP_FACES)) // face_sz,
        "leafs": nleafs,
        "nodes": len(lump(LUMP_NODES)) // node_sz,
        "clipnodes": len(lump(LUMP_CLIPNODES)) // clip_sz,
        "marksurfaces": len(lump(LUMP_MARKSURFACES)) // mark_sz,
        "models": len(models) // MODEL_SIZE,
        "visleafs": visleafs,
        "visdata_bytes": len(vis),
        "vis_leaves": round(total_leaves / n, 1),
        "vis_faces": round(total_faces / n, 1),
    }


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    rc = 0
    for p in argv[1:]:
        try:
            print(json.dumps(stats(p)))
        except (OSError, ValueError, struct.error) as e:
            print(json.dumps({"path": p, "error": str(e)}))
            rc = 1
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv))
