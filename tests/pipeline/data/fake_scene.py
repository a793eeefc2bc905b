#!/usr/bin/env python3
"""A stand-in for a scene driver (tests/pipeline/scene_index.sh, index_browser.sh): writes what a
scene report writes into -o DIR, as its KIND says, in no time.

    fake_scene.py KIND NAME [--quick] -o DIR

KIND: pass (every check passes), fail (one check fails), crash (exits 1, no scene.json),
silent (exits 0 but writes no scene.json), broken (a scene.json pointing at a missing chart).
"""
import json
import struct
import sys
import zlib
from pathlib import Path


def png(width, height, rgb):
    """A small valid PNG of one colour (no matplotlib needed)."""
    raw = b"".join(b"\x00" + bytes(rgb) * width for _ in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw))
            + chunk(b"IEND", b""))


def main():
    kind, name = sys.argv[1], sys.argv[2]
    out = Path(sys.argv[sys.argv.index("-o") + 1])
    print(f"fake {name}: {kind}")
    if kind == "crash":
        print("fake driver: sig-solve failed", file=sys.stderr)
        return 1
    out.mkdir(parents=True, exist_ok=True)
    (out / "report.md").write_text(f"# {name}\n")
    if kind == "silent":
        return 0
    (out / "speed_accuracy.png").write_bytes(png(40, 30, (200, 30, 30)))
    (out / "stability.png").write_bytes(png(30, 20, (30, 30, 200)))
    (out / "N8" / "run").mkdir(parents=True, exist_ok=True)
    (out / "N8" / "run" / "case.pvd").write_text("<VTKFile/>\n")
    charts = {"speed_accuracy": "speed_accuracy.png", "stability": "stability.png"}
    if kind == "broken":
        charts["extra"] = "no_such_chart.png"
    entry = {
        "scene": name, "title": f"Fake scene {name} <&>", "report": "report.md",
        "command": f"drivers/{name}.sh --quick", "seconds": 1.5,
        "checks": [{"name": "pressure within 2 %", "pass": True, "detail": "ours 1.01"},
                   {"name": "iterations", "pass": kind != "fail", "detail": "ours 9 (thesis 8)"},
                   {"name": "slope", "pass": None, "detail": "fewer than two meshes"}],
        "key_table": {"caption": "Table 7.1: ours (thesis)", "header": ["c", "iterations"],
                      "rows": [["1", "12 (11)"], ["10", "Nv (8)"]]},
        "charts": charts, "pvd": ["N8/run/case.pvd"]}
    (out / "scene.json").write_text(json.dumps(entry, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
