"""What the GetFEM comparison scripts (getfem_hertz.py, getfem_ring.py) share: reading a deck's
cards, and the version of Debian's python3-getfem."""
import subprocess


def deck_cards(path):
    """{KEYWORD: {field: value}} of a datafile (first card of each keyword; names lower-case)."""
    cards = {}
    for line in path.read_text().splitlines():
        words = line.split("#", 1)[0].split()
        if words:
            cards.setdefault(words[0].upper(),
                             dict(w.lower().split("=", 1) for w in words[1:] if "=" in w))
    return cards


def getfem_version():
    try:
        return subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "python3-getfem"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "5.4 (version not found)"
