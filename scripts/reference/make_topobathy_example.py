#!/usr/bin/env python3
"""Writes the real-data example of surface fitting (examples/data/topobathy_grid.csv and
examples/data/topobathy_scattered.csv) from the topography and bathymetry grid that
matplotlib's wheel ships as sample data (mpl-data/sample_data/topobathy.npz: 91 x 120
elevations in metres on a longitude-latitude grid, 126 to 122 degrees west, 48 to 50 degrees
north: the Strait of Georgia, Vancouver Island and the coast mountains, sea floor to peaks).

Coordinates (kilometres, so that chord-length parameters weigh x, y and z alike):
  x = (longitude - 234.0167) * 111.32 * cos(49 degrees), y = (latitude - 48.01637) * 110.57,
  z = elevation / 1000.

Degrees, a stated model of confidence in the measurements (docs/fitting.md):
  depth  = max(0, -z) / 1.5, capped at 1 (echo soundings lose accuracy with depth);
  slope  = |grad z| by central differences on the full grid (km per km);
  truth         = 0.95 - 0.5 depth           (0.45 .. 0.95: high on land, falling with depth);
  indeterminacy = 0.05 + 0.5 slope / (slope + 0.1)  (0.05 .. 0.55: rising on steep ground);
  falsity       = 0.05 + 0.2 depth           (0.05 .. 0.25).
Every triple lies in [0, 1]^3, so it is valid under the neutrosophic rule.

The grid file is every second row and column of the data (46 x 60 = 2,760 points, rows along
x); the scattered file is 1,500 points of the full grid chosen at random (seed 20261203), in
random order.

Run (PyPI's matplotlib wheel is read as a zip; nothing is installed):
  python3 -m pip download --no-deps matplotlib==3.10.3 -d /tmp/mpl
  .venv-ref/bin/python scripts/reference/make_topobathy_example.py /tmp/mpl/matplotlib-3.10.3-*.whl
(numpy only.) The sample data is distributed with matplotlib under the Matplotlib License
(the license agreement for matplotlib versions 1.3.0 and later, a PSF-style licence; the
LICENSE file of the wheel's dist-info).
"""

import io
import sys
import zipfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "examples/data"
MEMBER = "matplotlib/mpl-data/sample_data/topobathy.npz"

HEADER = """# Real terrain and sea floor: the topography and bathymetry grid shipped with matplotlib
# (mpl-data/sample_data/topobathy.npz, matplotlib 3.10.3, under the Matplotlib License), 126
# to 122 W, 48 to 50 N. {what}
# x, y, z in km (x east, y north from the grid's south-west corner; z = elevation / 1000).
# Degrees (a stated model, docs/fitting.md): depth = min(1, max(0, -z) / 1.5), slope = |grad z|;
# truth = 0.95 - 0.5 depth, indeterminacy = 0.05 + 0.5 slope / (slope + 0.1),
# falsity = 0.05 + 0.2 depth. Made by scripts/reference/make_topobathy_example.py.
"""


def main(wheel):
    with zipfile.ZipFile(wheel) as archive:
        data = np.load(io.BytesIO(archive.read(MEMBER)))
        topo = data["topo"].astype(np.float64)
        lon = data["longitude"].astype(np.float64)
        lat = data["latitude"].astype(np.float64)
    x = (lon - lon[0]) * 111.32 * np.cos(np.radians(49.0))
    y = (lat - lat[0]) * 110.57
    z = topo / 1000.0
    # The grid's rows are latitudes: rows along x are its columns.
    X, Y = np.meshgrid(x, y, indexing="xy")
    dz_dy, dz_dx = np.gradient(z, y, x)
    slope = np.hypot(dz_dx, dz_dy)
    depth = np.minimum(1.0, np.maximum(0.0, -z) / 1.5)
    truth = 0.95 - 0.5 * depth
    indeterminacy = 0.05 + 0.5 * slope / (slope + 0.1)
    falsity = 0.05 + 0.2 * depth
    columns = np.stack([X, Y, z, truth, indeterminacy, falsity], axis=-1)  # (lat, lon, 6)

    def write(name, rows, what):
        with open(OUT / name, "w") as f:
            f.write(HEADER.format(what=what))
            f.write("x,y,z,truth,indeterminacy,falsity\n")
            for r in rows:
                f.write(",".join(f"{v:.6g}" for v in r) + "\n")

    # Rows along x: point k cols + l is on row k (the k-th longitude) and column l.
    sub = columns[::2, ::2].transpose(1, 0, 2)  # (lon, lat, 6)
    rows, cols = sub.shape[:2]
    write(
        "topobathy_grid.csv",
        sub.reshape(-1, 6),
        f"Every second point: a grid of {rows} x {cols} points,\n# row by row (rows along x), "
        f"for `fit --surface --grid {rows}x{cols}`.",
    )
    rng = np.random.default_rng(20261203)
    flat = columns.reshape(-1, 6)
    chosen = rng.choice(len(flat), size=1500, replace=False)
    write(
        "topobathy_scattered.csv",
        flat[chosen],
        "1,500 points of the full grid chosen at\n# random, in random order, for "
        "`fit --surface --projection xy`.",
    )


if __name__ == "__main__":
    main(sys.argv[1])
