#!/usr/bin/env python3
"""Spreadsheet fixtures for the table-reading tests
(crates/neutrospline-cli/tests/integration/dialects.rs), written once by openpyxl and by
LibreOffice, from the same rows as make_table_dialect_fixtures.py's `*-plain.csv` files:

- `workbook.xlsx` (openpyxl): sheet `Points` holds the paper's Example 1 from cell A1, numbers
  as number cells and names as text; sheet `Survey` holds the first 12 points of the survey
  data from cell B3 (two empty rows and an empty column before it, so row numbers in messages
  are the sheet's), one x value typed as text (`'12.5` as a user types it), and the headings
  `mu` and `nu` for truth and falsity;
- `workbook.ods` and `workbook.xls`: `workbook.xlsx` converted by LibreOffice
  (`soffice --headless --convert-to ods|xls`), as LibreOffice Calc and Excel 97-2003 save it;
- `error-cell.xlsx` (openpyxl): Example 1 with the error value `#DIV/0!` as C2's truth (row 4
  of the sheet), as a formula that divides by zero leaves it.

Run: .venv-ref/bin/python scripts/reference/make_spreadsheet_fixtures.py
(needs openpyxl from PyPI, and soffice from Debian's libreoffice-calc-nogui).
"""

import csv
import shutil
import subprocess
import tempfile
from pathlib import Path

import openpyxl

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "crates/neutrospline-cli/tests/data/tables"


def rows_of(name):
    with open(OUT / name, newline="") as f:
        return list(csv.reader(f))


def cell_value(heading, text):
    return text if heading == "name" else float(text)


def put(sheet, rows, row0=1, col0=1, rename=None, as_text=()):
    header = rows[0]
    for c, heading in enumerate(header):
        sheet.cell(row=row0, column=col0 + c, value=(rename or {}).get(heading, heading))
    for r, row in enumerate(rows[1:], start=1):
        for c, (heading, text) in enumerate(zip(header, row)):
            value = text if (r, heading) in as_text else cell_value(heading, text)
            sheet.cell(row=row0 + r, column=col0 + c, value=value)


def main():
    example1 = rows_of("example1-plain.csv")
    survey = rows_of("survey-plain.csv")

    book = openpyxl.Workbook()
    points = book.active
    points.title = "Points"
    put(points, example1)
    put(
        book.create_sheet("Survey"),
        survey,
        row0=3,
        col0=2,
        rename={"truth": "mu", "falsity": "nu"},
        as_text={(5, "x")},
    )
    book.save(OUT / "workbook.xlsx")

    with tempfile.TemporaryDirectory() as tmp:
        for ext in ["ods", "xls"]:
            subprocess.run(
                [
                    "soffice",
                    f"-env:UserInstallation=file://{tmp}/profile",
                    "--headless",
                    "--convert-to",
                    ext,
                    "--outdir",
                    tmp,
                    str(OUT / "workbook.xlsx"),
                ],
                check=True,
                capture_output=True,
            )
            shutil.copy(Path(tmp) / f"workbook.{ext}", OUT / f"workbook.{ext}")

    book = openpyxl.Workbook()
    points = book.active
    points.title = "Points"
    put(points, example1)
    # Row 4 of the sheet (C2), column D (truth): an error value, as =1/0 leaves it.
    points.cell(row=4, column=4, value="#DIV/0!")
    assert points.cell(row=4, column=4).data_type == "e"
    book.save(OUT / "error-cell.xlsx")


if __name__ == "__main__":
    main()
