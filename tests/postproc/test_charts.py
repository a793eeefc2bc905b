"""sigreport.charts: the speed-against-accuracy chart labels a spot once, Nv runs sit on the top
edge; the stability map draws every status."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from sigreport import MapCell, MapPanel, Point, Series, speed_accuracy_chart, stability_map  # noqa: E402
from sigreport.charts import _annotate_once  # noqa: E402


def test_labels_of_coinciding_points_are_written_once():
    fig, ax = plt.subplots()
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.plot([0.1, 0.101, 0.5, 10], [1e-2, 1e-2, 1e-2, 1e-3], "o")
    fig.canvas.draw()
    # Exact methods on one mesh: the same error, nearly the same time (7a's "N=128N=128").
    _annotate_once(ax, [(0.1, 1e-2, "N=128"), (0.101, 1e-2, "N=128"), (0.101, 1e-2, "r=1e6"),
                        (0.5, 1e-2, "N=128"), (10, 1e-3, "N=256")], fontsize=7)
    texts = [t.get_text() for t in ax.texts]
    assert texts.count("N=128") == 2  # once at 0.1, once at the distant 0.5
    assert "r=1e6" in texts and "N=256" in texts
    renderer = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(renderer) for t in ax.texts]
    assert not any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1:])
    plt.close(fig)


def test_speed_accuracy_png_with_nv(tmp_path):
    series = [Series("PDAS", [Point(0.2, 3e-3, "N=128"), Point(0.5, 1e-3, "N=256")]),
              Series("projection", [Point(0.3, None, "N=128")], marker="s", line="")]
    path = speed_accuracy_chart(tmp_path / "sa.png", series, "time (s)", "error (-)", "test")
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_stability_map_png(tmp_path):
    statuses = ["ok", "Nv", "missing", "sway", "drift", "gain+chatter", "dissipates"]
    cells = [[MapCell(s, s, 10 * (i + 1) if s in ("ok", "sway", "drift") else None)
              for i, s in enumerate(statuses)]]
    panels = [MapPanel("all statuses", ["N = 128"], statuses, cells, xlabel="status (-)",
                       ylabel="mesh (-)"),
              MapPanel("one", ["N = 128"], ["1e3"], [[MapCell("59", "ok", 59)]],
                       xlabel="gamma (GPa/m)", ylabel="mesh (-)")]
    path = stability_map(tmp_path / "map.png", panels, value_label="Newton (iterations)")
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
