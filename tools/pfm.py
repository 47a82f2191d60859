"""PFM images as numpy arrays, for the repository's Python (scripts/gpu-check, the tests)."""
import numpy as np


def read_pfm(path, dtype=np.float32):
    """A PFM file, colour ('PF') or grey ('Pf'), as an (H, W, 3) or (H, W, 1) array of `dtype`,
    rows from the top (PFM stores them bottom to top)."""
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        if kind not in (b'PF', b'Pf'):
            raise ValueError(f'{path}: not a PFM image')
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype='<f4' if scale < 0 else '>f4')
    return data.reshape(height, width, 3 if kind == b'PF' else 1)[::-1].astype(dtype)
