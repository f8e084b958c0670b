"""Spreadsheets (.xlsx, .ods, .xls) read by `load` as the command line reads them: the first
sheet or the one `sheet=` names, with the table options of the command line (`columns`,
`ignore_columns`, ...), to the same model as the CSV file with the same rows."""

import csv

import numpy as np
import openpyxl
import pytest

import neutrospline as ns


def tables(root):
    return root / "crates/neutrospline-cli/tests/data/tables"


def control_values(model):
    return np.column_stack([model.positions, model.membership_degrees])


@pytest.mark.parametrize("book", ["workbook.xlsx", "workbook.ods", "workbook.xls"])
def test_the_fixtures_read_as_the_plain_csv(root, book):
    plain = ns.load(tables(root) / "example1-plain.csv")
    first = ns.load(tables(root) / book)
    named = ns.load(tables(root) / book, sheet="Points")
    assert first == plain
    assert named == plain
    # The control values are Table 1's, read exactly.
    assert control_values(first)[3].tolist() == [9.0, 5.0, 0.2, 0.4, 0.4]


def test_a_workbook_written_by_openpyxl_with_mapped_columns(root, tmp_path):
    with open(tables(root) / "example1-plain.csv", newline="") as f:
        rows = list(csv.reader(f))
    book = openpyxl.Workbook()
    book.active.title = "Notes"
    book.active["A1"] = "Example 1 of the paper"
    sheet = book.create_sheet("Control points")
    renamed = {"truth": "T", "falsity": "mu_false"}
    sheet.append([renamed.get(h, h) for h in rows[0]] + ["remark"])
    for row in rows[1:]:
        sheet.append([row[0]] + [float(v) for v in row[1:]] + ["checked"])
    path = tmp_path / "points.xlsx"
    book.save(path)
    model = ns.load(
        path,
        sheet="Control points",
        columns="falsity=mu_false",
        ignore_columns="remark",
    )
    assert model == ns.load(tables(root) / "example1-plain.csv")


def test_refusals_name_the_file_and_the_rule(root):
    book = tables(root) / "workbook.xlsx"
    with pytest.raises(ns.ModelError, match=r"sheet = Nope: the workbook has no such sheet "
                       r"\(its sheets: Points, Survey\)"):
        ns.load(book, sheet="Nope")
    with pytest.raises(ns.ModelError, match=r"sheet = Points applies to a spreadsheet"):
        ns.load(tables(root) / "example1-plain.csv", sheet="Points")
    with pytest.raises(ns.ModelError, match=r"error-cell\.xlsx\[Points\]:4: column `truth`: "
                       r"value `#DIV/0!` is not a number"):
        ns.load(tables(root) / "error-cell.xlsx")
    with pytest.raises(ns.ModelError, match=r"entities: is an option of a drawing"):
        ns.load(book, entities="SPLINE")
