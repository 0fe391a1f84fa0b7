"""A line chart as plain SVG, no dependencies: y against x on a logarithmic x axis.

Used by scale.py for report/figures/scale.svg; each series is a list of (x, y) points drawn
as a polyline with markers, in the series' colour and dash pattern.
"""

import math
from dataclasses import dataclass, field
from xml.sax.saxutils import escape


@dataclass
class Series:
    """One line: its legend label, colour, dash pattern ('' = solid) and points."""

    label: str
    color: str
    dash: str = ""
    points: list = field(default_factory=list)


def nice_step(span, ticks=6):
    """A round step (1, 2 or 5 times a power of ten) giving about `ticks` ticks over `span`."""
    raw = span / max(ticks, 1)
    power = 10 ** math.floor(math.log10(raw)) if raw > 0 else 1
    for m in (1, 2, 5, 10):
        if m * power >= raw:
            return m * power
    return 10 * power


def line_chart(series, title, x_label, y_label, width=760, height=440):
    """The SVG text of the chart; x must be positive (log axis), y starts at 0."""
    points = [p for s in series for p in s.points]
    if not points:
        raise ValueError("nothing to plot")
    left, right, top, bottom = 70, 230, 40, 55
    pw, ph = width - left - right, height - top - bottom
    x_lo = 10 ** math.floor(math.log10(min(x for x, _ in points)))
    x_hi = 10 ** math.ceil(math.log10(max(x for x, _ in points)))
    if x_hi <= x_lo:
        x_hi = x_lo * 10
    y_step = nice_step(max(y for _, y in points) or 1)
    y_hi = y_step * math.ceil((max(y for _, y in points) or 1) / y_step)

    def sx(x):
        return left + pw * (math.log10(x) - math.log10(x_lo)) / (math.log10(x_hi) - math.log10(x_lo))

    def sy(y):
        return top + ph * (1 - y / y_hi)

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">',
        f'<rect width="{width}" height="{height}" fill="white"/>',
        f'<text x="{left + pw / 2}" y="22" text-anchor="middle" font-size="15">{escape(title)}</text>',
    ]
    decade = x_lo
    while decade <= x_hi * 1.0001:
        x = sx(decade)
        out.append(f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{top + ph}" stroke="#ddd"/>')
        label = f"10<tspan dy='-5' font-size='9'>{round(math.log10(decade))}</tspan>"
        out.append(f'<text x="{x:.1f}" y="{top + ph + 18}" text-anchor="middle">{label}</text>')
        decade *= 10
    y = 0.0
    while y <= y_hi * 1.0001:
        py = sy(y)
        out.append(f'<line x1="{left}" y1="{py:.1f}" x2="{left + pw}" y2="{py:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{py + 4:.1f}" text-anchor="end">{y:g}</text>')
        y += y_step
    out.append(f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="#444"/>')
    out.append(
        f'<text x="{left + pw / 2}" y="{height - 12}" text-anchor="middle">{escape(x_label)}</text>'
    )
    out.append(
        f'<text transform="translate(18 {top + ph / 2}) rotate(-90)" text-anchor="middle">'
        f"{escape(y_label)}</text>"
    )
    for k, s in enumerate(series):
        pts = sorted(s.points)
        dash = f' stroke-dasharray="{s.dash}"' if s.dash else ""
        path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in pts)
        out.append(f'<polyline points="{path}" fill="none" stroke="{s.color}" stroke-width="2"{dash}/>')
        for x, y in pts:
            out.append(f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="3.5" fill="{s.color}"/>')
        ly = top + 10 + 20 * k
        lx = left + pw + 15
        out.append(
            f'<line x1="{lx}" y1="{ly}" x2="{lx + 28}" y2="{ly}" stroke="{s.color}" stroke-width="2"{dash}/>'
        )
        out.append(f'<text x="{lx + 34}" y="{ly + 4}">{escape(s.label)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
