"""Reads 8-bit PNG files into numpy arrays (height, width, 4), for the web tests' pixel checks.

Only what screenshots and the page's images use: 8 bits per channel, grey, grey + alpha, RGB or RGBA, not
interlaced. Anything else is refused by name, never guessed at."""

import struct
import zlib

import numpy as np

_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # colour type -> channels


def decode(data, name="image"):
    """The pixels of a PNG as uint8 RGBA, shape (height, width, 4)."""
    if data[:8] != _SIGNATURE:
        raise ValueError(f"{name}: not a PNG file")
    pos, idat, header = 8, [], None
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if header is None:
        raise ValueError(f"{name}: PNG without IHDR")
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in _CHANNELS or interlace:
        raise ValueError(f"{name}: PNG with bit depth {depth}, colour type {colour}, interlace {interlace}: "
                         "only 8-bit non-interlaced grey/RGB(A) is read")
    channels = _CHANNELS[colour]
    stride = width * channels
    raw = np.frombuffer(zlib.decompress(b"".join(idat)), dtype=np.uint8)
    if raw.size != height * (stride + 1):
        raise ValueError(f"{name}: PNG image data is {raw.size} bytes, expected {height * (stride + 1)}")
    rows = raw.reshape(height, stride + 1)
    out = np.zeros((height, stride), dtype=np.uint8)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind, line = rows[y, 0], rows[y, 1:].astype(np.int32)
        if kind == 0:
            cur = line
        elif kind == 1:
            cur = _unfilter_left(line, channels, lambda left, i: left)
        elif kind == 2:
            cur = (line + prev) & 255
        elif kind == 3:
            cur = _unfilter_left(line, channels, lambda left, i: (left + int(prev[i])) >> 1)
        elif kind == 4:
            def paeth(left, i):
                return _paeth(left, int(prev[i]), int(prev[i - channels]) if i >= channels else 0)

            cur = _unfilter_left(line, channels, paeth)
        else:
            raise ValueError(f"{name}: PNG row {y} has filter type {kind}")
        out[y] = cur
        prev = cur.astype(np.int32)
    pixels = out.reshape(height, width, channels)
    if channels == 4:
        return pixels
    rgba = np.full((height, width, 4), 255, dtype=np.uint8)
    if channels in (1, 2):
        rgba[..., :3] = pixels[..., :1]
        if channels == 2:
            rgba[..., 3] = pixels[..., 1]
    else:
        rgba[..., :3] = pixels
    return rgba


def _unfilter_left(line, channels, predictor):
    """Undoes a filter whose prediction needs the pixel to the left, one byte at a time."""
    cur = line.tolist()
    for i in range(len(cur)):
        left = cur[i - channels] if i >= channels else 0
        cur[i] = (cur[i] + predictor(left, i)) & 255
    return np.array(cur, dtype=np.int32)


def _paeth(a, b, c):
    """Paeth 1991, the PNG predictor: the neighbour nearest a + b - c."""
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def read(path):
    with open(path, "rb") as f:
        return decode(f.read(), str(path))
