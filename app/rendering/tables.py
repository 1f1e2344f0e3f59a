"""Tables as self-contained HTML or SVG documents (``GET /relations?format=html|svg``).

A ``Table`` has column headings, row headings and cells; each cell has a state (``holds``,
``fails``, ``none`` for not applicable) that sets its colour and symbol, and a few lines of
text. Nothing here computes; the routers fill the table from the core's results.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from html import escape as html_escape
from typing import Literal
from xml.sax.saxutils import escape, quoteattr

State = Literal["holds", "fails", "none"]

#: Background colour and symbol of each state (colour-blind-safe blue / orange / grey).
STYLE: dict[str, tuple[str, str]] = {
    "holds": ("#d6eaf8", "\u2713 holds"),
    "fails": ("#fbe0cc", "\u2717 fails"),
    "none": ("#eeeeee", "\u2014 n/a"),
}


@dataclass(frozen=True)
class TableCell:
    """One cell: its verdict and its lines of text (residual, constants, note)."""

    state: State
    lines: tuple[str, ...] = ()
    title: str = ""
    """Longer text shown on hover (a note)."""


@dataclass
class Table:
    """A titled table of cells; ``rows`` pair a heading (lines) with one cell per column."""

    title: str
    subtitle: str = ""
    footnote: str = ""
    corner: str = ""
    """Heading of the row-heading column."""
    columns: list[tuple[str, str]] = field(default_factory=list)
    """(heading, description) per column."""
    rows: list[tuple[tuple[str, ...], list[TableCell]]] = field(default_factory=list)


def table_html(table: Table) -> str:
    """The table as one HTML document (inline style only, no script, no external resource)."""
    head = "".join(
        f'<th scope="col" title={quoteattr(description)}>{html_escape(heading)}</th>'
        for heading, description in table.columns
    )
    body = []
    for heading, cells in table.rows:
        name = "<br>".join(html_escape(line) for line in heading)
        tds = []
        for cell in cells:
            colour, symbol = STYLE[cell.state]
            text = "<br>".join(html_escape(line) for line in (symbol, *cell.lines))
            tds.append(
                f'<td class="{cell.state}" style="background:{colour}" '
                f"title={quoteattr(cell.title)}>{text}</td>"
            )
        body.append(f'<tr><th scope="row">{name}</th>{"".join(tds)}</tr>')
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f"<title>{html_escape(table.title)}</title>"
        "<style>body{font-family:DejaVu Sans,Helvetica,Arial,sans-serif;margin:1.5em}"
        "table{border-collapse:collapse}th,td{border:1px solid #999;padding:.4em .6em;"
        "vertical-align:top;font-size:.9em}td{font-family:DejaVu Sans Mono,monospace}"
        "thead th{background:#f4f4f4}caption{text-align:left;margin-bottom:.6em}"
        "p{color:#444;font-size:.9em}</style></head><body>"
        f"<h1>{html_escape(table.title)}</h1>"
        f"<p>{html_escape(table.subtitle)}</p>"
        f'<table><thead><tr><th scope="col">{html_escape(table.corner)}</th>{head}</tr></thead>'
        f"<tbody>{''.join(body)}</tbody></table>"
        f"<p>{html_escape(table.footnote)}</p></body></html>\n"
    )


def table_svg(table: Table) -> str:
    """The table as one SVG document (a grid of rectangles and text, with a viewBox)."""
    line_height, pad = 15, 6
    first_width, cell_width = 250, 190
    lines_per_row = [
        max(len(heading), *(1 + len(cell.lines) for cell in cells)) if cells else len(heading)
        for heading, cells in table.rows
    ]
    header_height = 2 * line_height + 2 * pad
    top = 56
    width = first_width + cell_width * len(table.columns) + 2 * pad
    heights = [n * line_height + 2 * pad for n in lines_per_row]
    height = top + header_height + sum(heights) + 40
    out = [
        '<svg xmlns="http://www.w3.org/2000/svg" class="dcosh-table" '
        f'viewBox="0 0 {width} {height}" width="{width}" height="{height}" role="img" '
        'aria-labelledby="table-title" font-family="DejaVu Sans, Helvetica, Arial, sans-serif" '
        'font-size="11">',
        f'<title id="table-title">{escape(table.title)}</title>',
        f'<rect x="0" y="0" width="{width}" height="{height}" fill="#ffffff"/>',
        f'<text x="{pad}" y="20" font-size="14" font-weight="bold">{escape(table.title)}</text>',
        f'<text x="{pad}" y="38" fill="#444444">{escape(table.subtitle)}</text>',
    ]
    y = top
    out.append('<g class="header">')
    out.append(
        f'<rect x="{pad}" y="{y}" width="{first_width}" height="{header_height}" '
        'fill="#f4f4f4" stroke="#999999"/>'
        f'<text x="{2 * pad}" y="{y + pad + line_height}" font-weight="bold">'
        f"{escape(table.corner)}</text>"
    )
    for k, (heading, description) in enumerate(table.columns):
        x = pad + first_width + k * cell_width
        out.append(
            f'<g class="column" data-id={quoteattr(heading)}><title>{escape(description)}</title>'
            f'<rect x="{x}" y="{y}" width="{cell_width}" height="{header_height}" '
            'fill="#f4f4f4" stroke="#999999"/>'
            f'<text x="{x + pad}" y="{y + pad + line_height}" font-weight="bold">'
            f"{escape(heading)}</text></g>"
        )
    out.append("</g>")
    y += header_height
    for (row_heading, cells), row_height in zip(table.rows, heights, strict=True):
        row_id = row_heading[0] if row_heading else ""
        out.append(f'<g class="row" data-id={quoteattr(row_id)}>')
        out.append(
            f'<rect x="{pad}" y="{y}" width="{first_width}" height="{row_height}" '
            'fill="#f4f4f4" stroke="#999999"/>'
        )
        out.extend(_text_lines(pad + pad, y + pad, line_height, row_heading, bold_first=True))
        for k, cell in enumerate(cells):
            x = pad + first_width + k * cell_width
            colour, symbol = STYLE[cell.state]
            out.append(
                f'<g class="cell {cell.state}"><title>{escape(cell.title or symbol)}</title>'
                f'<rect x="{x}" y="{y}" width="{cell_width}" height="{row_height}" '
                f'fill="{colour}" stroke="#999999"/>'
            )
            out.extend(_text_lines(x + pad, y + pad, line_height, (symbol, *cell.lines)))
            out.append("</g>")
        out.append("</g>")
        y += row_height
    out.append(
        f'<text x="{pad}" y="{y + 24}" font-size="10" fill="#555555">'
        f"{escape(table.footnote)}</text>"
    )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _text_lines(
    x: float, y: float, line_height: int, lines: tuple[str, ...], bold_first: bool = False
) -> list[str]:
    out = []
    for k, line in enumerate(lines):
        weight = ' font-weight="bold"' if bold_first and k == 0 else ""
        out.append(
            f'<text x="{x}" y="{y + (k + 1) * line_height - 3}"{weight}>{escape(line)}</text>'
        )
    return out
