#!/usr/bin/env python3
"""Draw where and how far the simulated flesh moves the skin, for docs/performance.md.

Reads two `lacrima export --format obj` files of the same frame, one of a shot with its "flesh"
key and one of the same shot without it, takes the vertices of one object (same order in both),
and splats each vertex's offset magnitude, seen from the front (world x right, y up), onto a
picture written as a binary PPM (convert it with oiiotool). Colour: dark at no offset, through red
to yellow at --full-scale millimetres and beyond. Pure Python (no numpy on these machines).

  tools/docs/flesh_offset_map.py with.obj without.obj out.ppm [--object face/ICTFace/M_Face]
                                 [--full-scale 0.2] [--size 480] [--floor 1e-4]
"""
import argparse
import math


def object_vertices(path, name):
    vertices, inside = [], False
    with open(path) as f:
        for line in f:
            if line.startswith("o "):
                inside = line[2:].strip() == name
            elif inside and line.startswith("v "):
                x, y, z = map(float, line.split()[1:4])
                vertices.append((x, y, z))
    if not vertices:
        raise SystemExit(f"{path}: no vertices of object {name}")
    return vertices


def colour(fraction):
    """Black -> red -> yellow -> white as the offset grows to and past the full scale."""
    t = max(0.0, min(1.0, fraction))
    return (min(1.0, 2.0 * t), max(0.0, min(1.0, 2.0 * t - 0.6)), max(0.0, 3.0 * t - 2.4))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("with_flesh")
    parser.add_argument("without_flesh")
    parser.add_argument("out")
    parser.add_argument("--object", default="face/ICTFace/M_Face")
    parser.add_argument("--full-scale", type=float, default=0.2, help="millimetres drawn brightest")
    parser.add_argument("--size", type=int, default=480)
    parser.add_argument("--floor", type=float, default=1e-4,
                        help="millimetres below which a vertex counts as still (float rounding in renewed normals)")
    args = parser.parse_args()
    a = object_vertices(args.with_flesh, args.object)
    b = object_vertices(args.without_flesh, args.object)
    if len(a) != len(b):
        raise SystemExit("the two files' objects have different vertex counts")
    xs = [p[0] for p in b]
    ys = [p[1] for p in b]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    scale = (args.size - 1) / max(x1 - x0, y1 - y0)
    width, height = int((x1 - x0) * scale) + 1, int((y1 - y0) * scale) + 1
    # Per pixel: the largest offset of the vertices landing there, and whether any skin does (grey).
    offset = [[-1.0] * width for _ in range(height)]
    for (pa, pb) in zip(a, b):
        px = int((pb[0] - x0) * scale)
        py = height - 1 - int((pb[1] - y0) * scale)
        d = 1e3 * math.dist(pa, pb)
        if d > offset[py][px]:
            offset[py][px] = d
    largest = max(max(row) for row in offset)
    with open(args.out, "wb") as out:
        out.write(f"P6 {width} {height} 255\n".encode())
        for row in offset:
            pixels = bytearray()
            for d in row:
                if d < 0.0:
                    pixels += bytes((16, 16, 24))
                elif d <= args.floor:
                    pixels += bytes((70, 70, 78))
                else:
                    r, g, bl = colour(d / args.full_scale)
                    pixels += bytes((int(255 * max(r, 0.28)), int(255 * max(g, 0.1)), int(255 * max(bl, 0.1))))
            out.write(pixels)
    print(f"{args.out}: {width}x{height}, largest offset {largest:.4f} mm")


if __name__ == "__main__":
    main()
