"""What the app tests read from screenshots of the 3D view."""
from __future__ import annotations

import io

from PIL import Image


def pixels_on_the_border(png: bytes, inset: int = 2) -> int:
    """Pixels of the view's border (a frame `inset` px in, off the JPEG's edge) that are not
    the background: Slicer's gradient is blue-dominant (blue exceeds red and green by 35+), the
    robot (grey, black, orange), the phantom's grey slices and its yellow outline are not. A
    model cut by the view's edge leaves such pixels on the border."""
    image = Image.open(io.BytesIO(png)).convert('RGB')
    w, h = image.size
    border = [(x, y) for x in range(inset, w - inset) for y in (inset, h - 1 - inset)] + \
             [(x, y) for y in range(inset, h - inset) for x in (inset, w - 1 - inset)]
    return sum(1 for x, y in border if (lambda r, g, b: b - max(r, g) < 20)(*image.getpixel((x, y))))
