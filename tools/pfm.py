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


def write_pfm(path, image):
    """An (H, W, 3) or (H, W, 1) array as a little-endian PFM file, rows from the top."""
    image = np.asarray(image, dtype='<f4')
    kind = b'PF' if image.shape[2] == 3 else b'Pf'
    with open(path, 'wb') as f:
        f.write(kind + b'\n%d %d\n-1.0\n' % (image.shape[1], image.shape[0]))
        f.write(np.ascontiguousarray(image[::-1]).tobytes())
