"""Small multiples of log-log line charts as plain SVG (no plotting library needed).

Each panel is one scene: RMSE against seconds, one line per renderer. Decades are marked
on both axes; a series is a (label, colour, dash, points) tuple.
"""

from __future__ import annotations

import math
from xml.sax.saxutils import escape

PANEL_W, PANEL_H, LEFT, TOP, BOTTOM, GAP = 330, 250, 58, 34, 42, 20


def _decades(lo: float, hi: float) -> tuple[float, float]:
    return 10 ** math.floor(math.log10(lo)), 10 ** math.ceil(math.log10(hi))


def _panel(x0: float, y0: float, title: str, series, x_label: str, y_label: str) -> list[str]:
    pts = [p for _, _, _, ps in series for p in ps if p[0] > 0 and p[1] > 0]
    if not pts:
        return []
    xl, xh = _decades(min(p[0] for p in pts), max(p[0] for p in pts))
    yl, yh = _decades(min(p[1] for p in pts), max(p[1] for p in pts))
    xh, yh = (xh * 10 if xh <= xl else xh), (yh * 10 if yh <= yl else yh)
    pw, ph = PANEL_W - LEFT - 10, PANEL_H - TOP - BOTTOM

    def sx(x):
        return x0 + LEFT + pw * (math.log10(x) - math.log10(xl)) / math.log10(xh / xl)

    def sy(y):
        return y0 + TOP + ph * (1 - (math.log10(y) - math.log10(yl)) / math.log10(yh / yl))

    out = [f'<text x="{x0 + LEFT + pw / 2}" y="{y0 + 18}" text-anchor="middle" '
           f'font-size="13">{escape(title)}</text>',
           f'<rect x="{x0 + LEFT}" y="{y0 + TOP}" width="{pw}" height="{ph}" fill="none" '
           'stroke="#888"/>']
    d = xl
    while d <= xh * 1.0001:
        out += [f'<line x1="{sx(d)}" y1="{y0 + TOP}" x2="{sx(d)}" y2="{y0 + TOP + ph}" '
                'stroke="#ddd"/>',
                f'<text x="{sx(d)}" y="{y0 + TOP + ph + 14}" text-anchor="middle">{d:g}</text>']
        d *= 10
    d = yl
    while d <= yh * 1.0001:
        out += [f'<line x1="{x0 + LEFT}" y1="{sy(d)}" x2="{x0 + LEFT + pw}" y2="{sy(d)}" '
                'stroke="#ddd"/>',
                f'<text x="{x0 + LEFT - 4}" y="{sy(d) + 4}" text-anchor="end">{d:g}</text>']
        d *= 10
    out += [f'<text x="{x0 + LEFT + pw / 2}" y="{y0 + PANEL_H - 8}" '
            f'text-anchor="middle">{escape(x_label)}</text>',
            f'<text transform="translate({x0 + 14},{y0 + TOP + ph / 2}) rotate(-90)" '
            f'text-anchor="middle">{escape(y_label)}</text>']
    for label, colour, dash, ps in series:
        ps = [p for p in ps if p[0] > 0 and p[1] > 0]  # in the order given (by spp)
        if not ps:
            continue
        path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in ps)
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" '
                   f'stroke-width="1.8"{dash_attr}/>')
        out += [f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="2.5" fill="{colour}"/>'
                for x, y in ps]
    return out


def small_multiples(panels: dict, title: str, x_label: str, y_label: str,
                    columns: int = 3) -> str:
    """panels: {panel title: [series, ...]}; the legend is taken from the first panel."""
    n = len(panels)
    rows = max(1, math.ceil(n / columns))
    legend = next(iter(panels.values()), [])
    width = columns * PANEL_W + GAP
    height = rows * PANEL_H + 40 + 18 * len(legend) + 10
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="11">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{width / 2}" y="22" text-anchor="middle" font-size="15">'
           f'{escape(title)}</text>']
    for k, (name, series) in enumerate(panels.items()):
        out += _panel(GAP / 2 + (k % columns) * PANEL_W, 30 + (k // columns) * PANEL_H, name,
                      series, x_label, y_label)
    y = 30 + rows * PANEL_H + 10
    for label, colour, dash, _ in legend:
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        out += [f'<line x1="{GAP}" y1="{y}" x2="{GAP + 30}" y2="{y}" stroke="{colour}" '
                f'stroke-width="2"{dash_attr}/>',
                f'<text x="{GAP + 38}" y="{y + 4}">{escape(label)}</text>']
        y += 18
    return "\n".join(out + ["</svg>"]) + "\n"
