"""8-bit RGB/RGBA PNG files for the reference test, Python's standard library only: write rows of
pixels, and read the non-interlaced 8-bit RGBA or RGB PNGs Inkshade writes (libpng with its
adaptive filters, PNG specification section 9)."""
import struct
import zlib


def encode(width, height, pixels, channels=4):
    """The PNG file's bytes; pixels: bytes of `channels` (3 or 4) samples a pixel, row 0 at the top."""
    row = width * channels
    raw = b"".join(b"\x00" + bytes(pixels[y * row:(y + 1) * row]) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    colour_type = {3: 2, 4: 6}[channels]
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")


def write(path, width, height, pixels, channels=4):
    with open(path, "wb") as f:
        f.write(encode(width, height, pixels, channels))


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def _unfilter(kind, line, prev, bpp):
    if kind == 0:
        return line
    if kind == 2:
        return bytearray((x + y) & 255 for x, y in zip(line, prev))
    out = bytearray(line)
    for i in range(len(out)):
        a = out[i - bpp] if i >= bpp else 0
        if kind == 1:
            out[i] = (out[i] + a) & 255
        elif kind == 3:
            out[i] = (out[i] + ((a + prev[i]) >> 1)) & 255
        else:
            out[i] = (out[i] + _paeth(a, prev[i], prev[i - bpp] if i >= bpp else 0)) & 255
    return out


def read_rgba(path):
    """(width, height, RGBA bytes, row 0 at the top); RGB files get alpha 255."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + ": not a PNG file")
    pos, idat, header = 8, bytearray(), None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in (2, 6) or interlace:
        raise ValueError(path + ": only 8-bit RGB/RGBA non-interlaced PNGs are read")
    bpp = 4 if colour_type == 6 else 3
    raw, stride = zlib.decompress(bytes(idat)), width * bpp
    prev, rows = bytearray(stride), []
    for y in range(height):
        start = y * (stride + 1)
        prev = _unfilter(raw[start], bytearray(raw[start + 1:start + 1 + stride]), prev, bpp)
        rows.append(bytes(prev))
    pixels = b"".join(rows)
    if bpp == 3:
        out = bytearray(width * height * 4)
        out[0::4], out[1::4], out[2::4], out[3::4] = pixels[0::3], pixels[1::3], pixels[2::3], b"\xff" * (width * height)
        pixels = bytes(out)
    return width, height, pixels
