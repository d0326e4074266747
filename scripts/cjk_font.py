#!/usr/bin/env python3
"""Regenerates assets/fonts/NotoSansSC-Subset.otf: Noto Sans CJK SC Regular (SIL OFL
1.1, assets/fonts/OFL.txt) cut down to the characters Chinese text here needs.

Which characters: the 3755 hanzi of GB 2312's first level (the common characters a
name or a note is written in; listed by decoding the standard's rows 16 to 55, so
the list needs no download), CJK punctuation and full-width forms, and every CJK
character found in the repository's catalogues (the app's and the sheets'), scenes,
templates and in the design glossary beside it (so a word the app or a sheet says is
never missing), and the arrows and signs the tables write directions with.

Why a subset: the whole face is 16 MB; the app embeds this one on the desktop and
the web demo fetches it only when Chinese text is shown.

Needs Debian's fonts-noto-cjk (the source face) and fontTools (`pip install
fonttools`). Run from anywhere: python3 scripts/cjk_font.py
"""

import pathlib
import re

from fontTools import subset
from fontTools.ttLib import TTCollection

ROOT = pathlib.Path(__file__).resolve().parent.parent
SOURCE = pathlib.Path("/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc")
# Index of "Noto Sans CJK SC" in the collection (JP, KR, SC, TC, HK, then Mono).
SC_INDEX = 2
OUT = ROOT / "assets" / "fonts" / "NotoSansSC-Subset.otf"
CJK = re.compile(r"[\u2e80-\u9fff\uff00-\uffef\u3000-\u303f]")
# Where Chinese text is written: catalogues, scenes, templates, the glossary.
TEXT_GLOBS = ["locales/*", "crates/*/locales/*", "assets/scenes/*.ron", "assets/templates/*.ron",
              "assets/cams/*.ron", "src/**/*.rs", "crates/*/src/**/*.rs"]


def gb2312_level_one():
    """The first-level hanzi of GB 2312: rows 16 to 55 of the standard."""
    chars = []
    for row in range(16, 56):
        for cell in range(1, 95):
            try:
                chars.append(bytes([0xA0 + row, 0xA0 + cell]).decode("gb2312"))
            except UnicodeDecodeError:
                pass  # row 55 ends at cell 89
    return chars


def repository_text():
    found = set()
    files = [p for g in TEXT_GLOBS for p in ROOT.glob(g)]
    glossary = ROOT.parent / "shared" / "design" / "glossary_zh.md"
    if glossary.exists():
        files.append(glossary)
    for path in files:
        if path.is_file():
            found.update(CJK.findall(path.read_text(encoding="utf-8", errors="ignore")))
    return found


def main():
    chars = set(gb2312_level_one()) | repository_text()
    chars |= {chr(c) for c in range(0x3000, 0x3040)}  # CJK punctuation
    chars |= {chr(c) for c in range(0xFF01, 0xFF5F)}  # full-width forms
    # The tables' direction signs (⊥CD, ∥导路, C→D), which the Latin face lacks.
    chars |= set("→←↑↓⊥∥×")
    # Latin, Latin-1, Greek and the sheets' signs: a text that holds Chinese is set in
    # this face alone (a run shaped in two faces loses its Chinese in resvg where the
    # Latin face joins letters into a ligature, as "fi" in "profile").
    chars |= {chr(c) for c in range(0x20, 0x7F)} | {chr(c) for c in range(0xA0, 0x100)}
    chars |= {chr(c) for c in range(0x391, 0x3CA)}
    chars |= set("−–—‘’“”…′″•°±µ²³ⁿᵗ√∞≈≤≥")
    # Not the middle dot: this face's is full-width (the Chinese 间隔号), and a unit's
    # dot in a Chinese line read "kN · m". Without it, resvg takes the Latin face's for
    # that one character, and egui the Latin face's anyway.
    chars.discard("·")
    face = TTCollection(str(SOURCE)).fonts[SC_INDEX]
    options = subset.Options()
    options.layout_features = ["*"]
    options.name_IDs = ["*"]
    options.notdef_outline = True
    options.hinting = False  # egui and resvg draw unhinted
    options.desubroutinize = False
    sub = subset.Subsetter(options)
    sub.populate(unicodes=sorted(ord(c) for c in chars))
    sub.subset(face)
    OUT.parent.mkdir(parents=True, exist_ok=True)
    face.save(str(OUT))
    print(f"{OUT.relative_to(ROOT)}: {len(chars)} characters, {OUT.stat().st_size} bytes")


if __name__ == "__main__":
    main()
