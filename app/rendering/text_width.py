"""How wide a line of SVG text is, so that the SVG writer can wrap text instead of clipping it.

The pictures name DejaVu Sans first (``font-family="DejaVu Sans, Helvetica, Arial, sans-serif"``);
its advance widths (in em, rounded up to 1/50 em) for Latin, Greek, punctuation, sub- and
superscripts, arrows and mathematical operators are below, read once from the font's ``hmtx``
table. Helvetica and Arial are narrower, so a line that fits in DejaVu Sans fits in them too.
A character not in the table counts as 1 em (wider than most), and bold text as 1.27 times the
regular width (the largest ratio of DejaVu Sans Bold to Regular over ASCII is 1.262).
"""

from __future__ import annotations

#: (advance width in em, the code points with that width: hexadecimal, ranges inclusive).
_WIDTHS: tuple[tuple[float, str], ...] = (
    (0, "200b-200f 2028-202e 2060-2064 206a-206f"),
    (0.1, "200a"),
    (0.18, "2006 2044 2071 2097"),
    (0.2, "2009 202f"),
    (0.24, "2032 2035 205f"),
    (0.26, "2005 2041 207d-207e 208d-208e"),
    (0.28, "27 69-6a 6c ec-ef 374-375 3f3 2236"),
    (0.3, "49-4a cc-cf 37f 399 3aa 209c"),
    (0.32, "20 2c 2e a0 b7 387 2008 2018-201b 2027 205a 205d-205e 22c5"),
    (0.34, "2f 3a-3b 5c 7c a6 37e 390 3af 3b9 3ca 2004 2024 2038 204f 2129 2215"),
    (0.36, "66 2148-2149"),
    (0.38, "2d ad 2010-2011 2033 2036 209b 2139 2240"),
    (0.4, "28-29 5b 5d 74 2039-203a 2045-2046 207f 2090 2099"),
    (0.42, "21 72 a1 b2-b3 b9 38a 2070 2074-2079 2080-2089 2091-2092 2094-2095 2113"),
    (0.44, "2096 209a"),
    (0.46, "22 3dd 2052 2093"),
    (0.48, "aa ba 2110 2134 2137 226c"),
    (
        0.5,
        "2a 5f-60 a7-a8 af-b0 b4 b8 37a 384-385 2000 2002 2013 2016-2017 2020-2021 203c "
        "203e 2043 204a 204c-204e 2051 2223-2226",
    ),
    (0.52, "201c-201f 2202"),
    (
        0.54,
        "3f 73 7a bf 3ef 2034 2037 203d 207a-207c 208a-208c 214e 222b 222e 2231-2233 "
        "22a6-22a7 22ba",
    ),
    (0.56, "4c 63 e7 37b-37d 393 3ad 3b5-3b6 3bd-3be 3f2 2142-2143"),
    (0.58, "46 6b 371 3b0 3c5 3c7 3cb 3cd 3dc 2125 2132"),
    (0.6, "76 78-79 fd ff 3b3 3ba-3bb 3c2 3db 2022-2023 2056 212f"),
    (
        0.62,
        "50 54 59 61 65 6f ab bb dd-de e0-e5 e8-eb f0 f2-f6 f8 3a1 3a4-3a5 3ab 3b4 3b8 "
        "3bf-3c0 3c4 3cc 3d0-3d1 3d9 3e7 3e9 3ed-3ee 3f5-3f7 2107 2128 2130 2144 2147 "
        "214c-214d",
    ),
    (
        0.64,
        "24 30-39 45 53 62 64 67-68 6e 70-71 75 7b 7d a2-a5 b5-b6 c8-cb df f1 f9-fc fe "
        "395 39e 3a3 3ae 3b2 3b7 3bc 3c1 3c3 3e1 3eb 3f1 3f8 3fc 2007 2012 204b 2098 "
        "210e-210f 2201 2203-2204 220e 2216 2218-221c 2234-2235 2237 22c4 22c6",
    ),
    (0.66, "4b 370 373 377 39a 3ac 3b1 3c6 3c8 3cf 3d5 3da 3de-3df 3e5 3fb 2104 212a 2138 213e"),
    (0.68, "3d7 3f0 2025 2057 2136 2206-2207 2211"),
    (
        0.7,
        "41-43 52 56 58 5a c0-c5 c7 386 391-392 394 396 39b 3a7 3d2 3d4 3e8 3ec 3f9 3fe "
        "2102 2108 2111 2118 211f 2123 212b 2200",
    ),
    (0.72, "3fd 3ff 2119 212d 213c 2146 220a 220d 221d 22f4 22f7 22fc 22fe"),
    (0.74, "55 d9-dc 2048-2049 2112 213d 2227-222a 228c-228e 22bb-22bd 22ce-22cf"),
    (0.76, "48 4e d1 376 388 397 39d 3a0 3e4 210c 2124 2135 220f-2210"),
    (0.78, "26 44 47 d0 3a9 3ea 2126-2127 2141 214b"),
    (
        0.8,
        "4f 51 d2-d6 d8 398 39f 3a6 3a8 3d8 3e6 3f4 205b 211a-211b 211d 212c 2131 222c "
        "222f 2293-2294",
    ),
    (0.82, "77 38c 203f-2040 2050 2054 2114-2115 211c 2140 2145"),
    (
        0.84,
        "23 2b 3c-3e 5e 7e ac b1 d7 f7 38e-38f 3c9 3ce 3d6 3e3 203b 2055 2058-2059 205c "
        "2190-21ff 2212-2214 2217 221e-221f 2222 2238-223f 2241-2253 2256-2269 "
        "226d-228b 228f-2292 2295-22a1 22b0-22b5 22b8-22b9 22be-22c3 22c7 22cd "
        "22d0-22d7 22da-22ed",
    ),
    (0.86, "3d3 210d 212e 213f"),
    (
        0.88,
        "4d 372 389 39c 3e0 3fa 2205 2208-2209 220b-220c 22a2-22a5 22a8-22af 22f3 "
        "22f5-22f6 22f8-22f9 22fb 22fd 22ff",
    ),
    (0.9, "211e 2220-2221"),
    (0.94, "3e2 2047 213a"),
    (0.96, "25 2109"),
    (0.98, "6d bc-be c6"),
    (
        1,
        "40 57 a9 ae e6 2001 2003 2014-2015 2026 2042 2053 210b 2117 2122 2254-2255 "
        "22b6-22b7 22c8-22cc 22ee-22f2 22fa",
    ),
    (1.02, "2100-2101 2105 2120"),
    (1.06, "2116 222d 2230 226a-226b"),
    (1.08, "2106 2121 2133"),
    (1.14, "2103"),
    (1.2, "213b"),
    (1.36, "2030"),
    (1.44, "22d8-22d9"),
    (1.74, "2031"),
)


def _table() -> dict[int, float]:
    out: dict[int, float] = {}
    for width, ranges in _WIDTHS:
        for item in ranges.split():
            low, _, high = item.partition("-")
            for code in range(int(low, 16), int(high or low, 16) + 1):
                out[code] = width
    return out


_EM = _table()

#: Width of a character the table does not hold, in em.
UNKNOWN_EM = 1.0

#: Bold text is at most this much wider than regular text.
BOLD_FACTOR = 1.27


def text_width(text: str, font_size: float, bold: bool = False) -> float:
    """The width in pixels of ``text`` on one line at ``font_size`` (an upper estimate)."""
    em = sum(_EM.get(ord(c), UNKNOWN_EM) for c in text)
    return em * font_size * (BOLD_FACTOR if bold else 1.0)


def wrap(text: str, width: float, font_size: float, bold: bool = False) -> list[str]:
    """``text`` broken at spaces into lines no wider than ``width`` pixels.

    A single word wider than the line is broken after ``/``, ``,``, ``&``, ``;`` or ``=`` where
    it can be (long URLs), else between characters.
    """
    lines: list[str] = []
    current = ""
    for word in text.split(" "):
        candidate = f"{current} {word}" if current else word
        if text_width(candidate, font_size, bold) <= width:
            current = candidate
            continue
        if text_width(word, font_size, bold) <= width:
            lines.append(current)
            current = word
            continue
        # a word longer than a line: its pieces fill the current line, then the next ones
        current = f"{current} " if current else ""
        for piece in _pieces(word, width, font_size, bold):
            candidate = current + piece
            if current.strip() and text_width(candidate, font_size, bold) > width:
                lines.append(current.rstrip())
                current = piece
            else:
                current = candidate
    if current or not lines:
        lines.append(current)
    return lines


def _pieces(word: str, width: float, font_size: float, bold: bool) -> list[str]:
    """A word cut after its break characters, each piece no wider than ``width``."""
    pieces: list[str] = []
    start = 0
    for k, c in enumerate(word):
        if c in "/,&;=?":
            pieces.append(word[start : k + 1])
            start = k + 1
    if start < len(word):
        pieces.append(word[start:])
    out: list[str] = []
    for piece in pieces:
        while text_width(piece, font_size, bold) > width and len(piece) > 1:
            cut = len(piece) - 1
            while cut > 1 and text_width(piece[:cut], font_size, bold) > width:
                cut -= 1
            out.append(piece[:cut])
            piece = piece[cut:]
        out.append(piece)
    return out
