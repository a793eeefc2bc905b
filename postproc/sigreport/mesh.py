"""A run's mesh (its NOPO file, case.nopo, read through sig-dump like every file of the stages),
for the reports that draw the deformed body or take norms of displacement fields:

    mesh = Mesh.read(run_dir / "case.nopo")
    mesh.xy, mesh.tri        # node coordinates (n, 2); triangles (t, 3), nodes from 0
    mesh.edges               # NOPO edges (e, 2), nodes from 0 (empty when it has none)
    mesh.boundary()          # the edges of one triangle only, as node pairs
    mesh.strain_norm(u)      # ||eps(u)||_L2 of a P1 field u (2 values per node), exact
"""
from pathlib import Path

from .ds import sig_dump_json


class Mesh:
    """Node coordinates, triangles and edges of a NOPO file, and the P1 strain map."""

    def __init__(self, xy, tri, edges=None):
        import numpy as np
        self.xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        self.tri = np.asarray(tri, dtype=int).reshape(-1, 3)
        self.edges = np.asarray(edges if edges is not None else [], dtype=int).reshape(-1, 2)
        self._grad = None

    @classmethod
    def read(cls, path):
        """case.nopo (sig-dump --json --values): coordinates, triangle_nodes and, when present,
        the edges (a, b, reference) triples; node numbers from 0."""
        import numpy as np
        dump = sig_dump_json(Path(path), values=True)
        edges = np.array(dump.get("edges", []), dtype=int).reshape(-1, 3)[:, :2] - 1
        return cls(dump["coordinates"], np.array(dump["triangle_nodes"]) - 1, edges)

    def _gradients(self):
        """Areas and barycentric-coordinate gradients (T, 3, 2) of the triangles, once."""
        if self._grad is None:
            import numpy as np
            p = self.xy[self.tri]
            d1, d2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
            det = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
            g1 = np.stack([d2[:, 1], -d2[:, 0]], axis=1) / det[:, None]
            g2 = np.stack([-d1[:, 1], d1[:, 0]], axis=1) / det[:, None]
            self._grad = (0.5 * np.abs(det), np.stack([-g1 - g2, g1, g2], axis=1))
        return self._grad

    def strain_norm(self, u):
        """||eps(u)||_L2 of u (2 values per node), exact for P1 (post/error_norm.hpp's norm)."""
        import numpy as np
        area, grad = self._gradients()
        ue = np.asarray(u).reshape(-1, 2)[self.tri]
        du = np.einsum("tia,tib->tab", ue, grad)  # du_a / dx_b
        e11, e22 = du[:, 0, 0], du[:, 1, 1]
        e12 = 0.5 * (du[:, 0, 1] + du[:, 1, 0])
        return float(np.sqrt(np.sum(area * (e11 ** 2 + e22 ** 2 + 2 * e12 ** 2))))

    def boundary(self):
        """The boundary edges: the node pairs of one triangle only."""
        count = {}
        for t in self.tri:
            for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                key = (min(a, b), max(a, b))
                count[key] = count.get(key, 0) + 1
        return [e for e, n in count.items() if n == 1]
