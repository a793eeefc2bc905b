"""Writing a text file whole or not at all."""
import os
import tempfile
from pathlib import Path


def write_text_atomically(path, text):
    """Write `text` to `path` through a temporary file in the same folder renamed into place, so
    a reader never sees half a file; the file gets the mode a plain open() would give it."""
    path = Path(path)
    handle, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    try:
        with os.fdopen(handle, "w") as f:
            f.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path
