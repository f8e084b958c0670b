#!/usr/bin/env python3
"""Spreadsheet-style CSV fixtures for the table-reading tests
(crates/neutrospline-cli/tests/integration/dialects.rs), written once by Python's csv module.

From the paper's Example 1 (examples/example1.csv) and the first 12 points of the survey data
(examples/data/survey.csv), each in the dialects spreadsheets save:

- `*-excel-fr.csv`: the `excel` dialect with `;` between cells and decimal commas (`0,3`),
  CRLF line ends, as Excel saves "CSV (semicolon-separated)" in a French or German locale;
- `*.tsv`: the `excel-tab` dialect (tabs), the degree columns named `mu` and `nu` (as
  docs/model.md writes the intuitionistic degrees) and an extra `note` column whose cells hold
  a comma, a semicolon and a quote (quoted by the csv module);
- `*-plain.csv`: the same rows as the project writes them, the reference each is read against.

Run: .venv-ref/bin/python scripts/reference/make_table_dialect_fixtures.py
(standard library only).
"""

import csv
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "crates/neutrospline-cli/tests/data/tables"


def rows_of(path, limit=None):
    lines = [l for l in path.read_text().splitlines() if l and not l.startswith("#")]
    reader = csv.DictReader(lines)
    rows = list(reader)
    return reader.fieldnames, rows[:limit] if limit else rows


def decimal_comma(text):
    return text.replace(".", ",")


def write(name, dialect, header, rows, **options):
    with open(OUT / name, "w", newline="") as f:
        writer = csv.writer(f, dialect=dialect, **options)
        writer.writerow(header)
        writer.writerows(rows)


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for stem, path, limit in [
        ("example1", ROOT / "examples/example1.csv", None),
        ("survey", ROOT / "examples/data/survey.csv", 12),
    ]:
        header, rows = rows_of(path, limit)
        numeric = [h for h in header if h != "name"]
        plain = [[r[h] for h in header] for r in rows]
        write(f"{stem}-plain.csv", "unix", header, plain, quoting=csv.QUOTE_MINIMAL)
        excel = [
            [r[h] if h == "name" else decimal_comma(r[h]) for h in header] for r in rows
        ]
        write(f"{stem}-excel-fr.csv", "excel", header, excel, delimiter=";")
        renamed = ["mu" if h == "truth" else "nu" if h == "falsity" else h for h in header]
        notes = [f'point {k}, "checked"; ok' for k in range(len(rows))]
        tab = [[r[h] for h in header] + [n] for r, n in zip(rows, notes)]
        write(f"{stem}.tsv", "excel-tab", renamed + ["note"], tab)
        assert numeric


if __name__ == "__main__":
    main()
