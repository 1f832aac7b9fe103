#!/usr/bin/env python3
"""Turns a terminal screen captured with `tmux capture-pane -p -e` (text with SGR colour codes) into an
HTML page, for a screenshot by headless Chromium (docs/editors.md: how neovim.png was made).
usage: pane-to-html.py PANE.ans OUT.html"""
import html
import re
import sys

BASE = ["#1e1e1e", "#e06c75", "#98c379", "#e5c07b", "#61afef", "#c678dd", "#56b6c2", "#dcdfe4",
        "#5c6370", "#ff7b86", "#b5e890", "#ffd68a", "#8cc8ff", "#e0a0f0", "#7fd8e0", "#ffffff"]


def colour(n):
    if n < 16:
        return BASE[n]
    if n < 232:
        n -= 16
        steps = [0, 95, 135, 175, 215, 255]
        return "#%02x%02x%02x" % (steps[n // 36], steps[n // 6 % 6], steps[n % 6])
    v = 8 + (n - 232) * 10
    return "#%02x%02x%02x" % (v, v, v)


def main():
    text = open(sys.argv[1], encoding="utf-8", errors="replace").read()
    out = []
    fg, bg, bold = None, None, False
    for part in re.split(r"(\x1b\[[0-9;]*m)", text):
        m = re.fullmatch(r"\x1b\[([0-9;]*)m", part)
        if not m:
            if part:
                style = ("color:%s;" % fg if fg else "") + ("background:%s;" % bg if bg else "") + ("font-weight:bold;" if bold else "")
                out.append('<span style="%s">%s</span>' % (style, html.escape(part)))
            continue
        codes = [int(c) if c else 0 for c in m.group(1).split(";")]
        i = 0
        while i < len(codes):
            c = codes[i]
            if c == 0:
                fg, bg, bold = None, None, False
            elif c == 1:
                bold = True
            elif c == 22:
                bold = False
            elif 30 <= c <= 37:
                fg = BASE[c - 30]
            elif 90 <= c <= 97:
                fg = BASE[c - 90 + 8]
            elif 40 <= c <= 47:
                bg = BASE[c - 40]
            elif 100 <= c <= 107:
                bg = BASE[c - 100 + 8]
            elif c == 39:
                fg = None
            elif c == 49:
                bg = None
            elif c in (38, 48) and i + 2 < len(codes) and codes[i + 1] == 5:
                if c == 38:
                    fg = colour(codes[i + 2])
                else:
                    bg = colour(codes[i + 2])
                i += 2
            i += 1
    with open(sys.argv[2], "w", encoding="utf-8") as f:
        f.write('<!doctype html><meta charset="utf-8"><body style="margin:0;background:#1e1e1e;color:#dcdfe4">'
                '<pre style="margin:8px;font:14px/1.3 \'DejaVu Sans Mono\',monospace">' + "".join(out) + "</pre>")


main()
