//! CSV tables: a header row, then one control point per row.
//!
//! Columns (case-insensitive): `x`, `y`, optional `z` (required for surfaces), `truth`,
//! `indeterminacy`, `falsity` (aliases `T`, `I`, `F`), `weight` (exactly for the NURBS kinds)
//! and an optional `name`. Lines starting with `#` are comments, empty lines are skipped, cells
//! are trimmed, rows end at LF, CRLF or CR, and a UTF-8 byte order mark is accepted. Quoting is
//! that of spreadsheets and Python's `csv` module: a cell starting with `"` is quoted (`""` in
//! it is a quote; commas and line ends in it are kept), a quote elsewhere is a character
//! (`C"0`); a file that ends inside a quoted cell is refused. One `csv` reader reads the whole
//! stream ([`Records`]). Line numbers in errors are physical lines of the file (1-based,
//! counted by LF, comments counted); a row's line is the one it starts on.
//!
//! A CSV file lists control points only: the kind, degree, knots and grid come from the
//! [`ReadOptions`](crate::ReadOptions) (the command line's `--kind`, `--degree`, `--knots`,
//! `--rows`, ...).

mod input;
mod records;
mod table;

pub(crate) use records::Records;
pub(crate) use table::{read_degrees, require_degrees, Columns, Table};

use std::io::BufRead;

use crate::parsed::{
    channel_problem, check_spread_value, duplicate_rule, present_channels, spread_from_values,
    spread_hint, spread_keys_problem, wide_channel, wide_lanes, Field, Origin, Parsed, PointRecord,
    SpreadKey,
};
use crate::settings::{Key, Kind, KnotSpec, KnotsSetting, Setting, Structure};
use crate::{InputError, ReadOptions};

/// Parses a CSV table held in memory; see [`parse_reader`].
pub(crate) fn parse(file: &str, bytes: &[u8], options: &ReadOptions) -> Result<Parsed, InputError> {
    parse_reader(file, bytes, options)
}

/// Parses a CSV table from a stream, line by line: an error is reported as soon as its line is
/// read, without reading further, and only the control points are kept in memory (at most
/// `max_control_points` of them). The `options` give the kind, the membership rule the
/// degrees must obey, and the structure.
pub(crate) fn parse_reader(
    file: &str,
    reader: impl BufRead,
    options: &ReadOptions,
) -> Result<Parsed, InputError> {
    let kind = options.kind.unwrap_or(Kind::DEFAULT);
    let membership = options.membership.unwrap_or_default();
    let columns = Columns {
        example: "`x,y,truth,indeterminacy,falsity`",
        column: &column,
        repeat_rule: duplicate_rule(),
        rows: "control points",
    };
    let mut table = Table::open(file, reader, &columns, &options.table)?
        .with_max_rows(options.limits.max_control_points);
    let has = |f: Field| table.has(Column::Field(f));
    for f in [Field::X, Field::Y] {
        table.require(Column::Field(f), f.name(), "every file needs x and y")?;
    }
    let present = present_channels(has, |c| table.has(Column::Channel(c)));
    if let Some(message) = channel_problem(membership, &present, "column") {
        return Err(table.header_error(message));
    }
    if membership.fits_degrees() {
        table.require(
            Column::Field(Field::Truth),
            Field::Truth.name(),
            "every membership rule requires it",
        )?;
        require_degrees(&table, membership, Column::Field)?;
    }
    if kind.is_surface() && !has(Field::Z) {
        return Err(table.header_error(
            "missing column `z` (surfaces are 3-D: every control point needs x, y and z)"
                .to_owned(),
        ));
    }
    if kind.is_rational() && !has(Field::Weight) {
        return Err(table.header_error(format!(
            "missing column `weight` (kind `{kind}` needs a positive weight for every control point)"
        )));
    }
    if !kind.is_rational() && has(Field::Weight) {
        return Err(table.header_error(format!(
            "column `weight` does not apply to kind `{kind}` (weights only apply to NURBS: \
             --kind nurbs or --kind nurbs-surface){}",
            FIT_HINT
        )));
    }
    let dimension = if has(Field::Z) { 3 } else { 2 };
    let mut spread_columns: [Option<&str>; 9] = [None; 9];
    for (column, heading) in table.named_columns() {
        if let Column::Spread(key) = column {
            spread_columns[key.index()] = Some(heading);
        }
    }
    if let Some(problem) = spread_keys_problem(&spread_columns, dimension, kind.is_surface()) {
        return Err(table.header_error(format!("column {problem}")));
    }

    let mut points = Vec::new();
    while let Some(row) = table.next_row()? {
        let mut values = [None::<f64>; 8];
        let mut wide = [None::<f64>; 9];
        let mut spreads = [None::<f64>; 9];
        let mut name = None;
        for cell in row.cells() {
            let field = match cell.column {
                Column::Field(field) => field,
                Column::Channel(c) => {
                    wide[c] = Some(row.number(&cell)?);
                    continue;
                }
                Column::Spread(key) => {
                    let value = row.number(&cell).and_then(|value| {
                        check_spread_value(value).map_err(|m| row.cell_error(&cell, m))
                    })?;
                    spreads[key.index()] = Some(value);
                    continue;
                }
            };
            if field == Field::Name {
                name = (!cell.text.is_empty()).then(|| cell.text.to_owned());
                continue;
            }
            let value = match (field, row.number_text(&cell)?.parse::<f64>()) {
                // Any number, NaN and infinities included: the core's NURBS weight rule judges it.
                (Field::Weight, Ok(w)) => w,
                _ => row.number(&cell)?,
            };
            values[field.index()] = Some(value);
        }
        let get = |f: Field| values[f.index()];
        let line = Some(row.line());
        let (degrees, second) = if membership.fits_degrees() {
            (read_degrees(&row, membership, &values)?, None)
        } else {
            let value = |name: &str| match wide_channel(name, false) {
                Some(c) => wide[c],
                None => Field::from_name(name, false).and_then(get),
            };
            let (first, second) =
                wide_lanes(membership, value).map_err(|e| row.error(None, e.to_string()))?;
            (first, Some(second))
        };
        points.push(PointRecord {
            name,
            position: [Field::X, Field::Y, Field::Z][..dimension]
                .iter()
                .map(|&f| get(f).unwrap_or_default())
                .collect(),
            degrees,
            second,
            weight: get(Field::Weight),
            origin: Origin { line, field: None },
            weight_origin: Origin {
                line,
                field: Some("column `weight`".to_owned()),
            },
            spread: spread_from_values(&spreads),
        });
    }
    Ok(Parsed {
        file: file.to_owned(),
        kind,
        name: None,
        description: None,
        membership,
        dimension,
        points,
        structure: structure(kind, options),
    })
}

/// The structure given on the command line (`--degree`, `--knots`, `--rows`, ...).
fn structure(kind: Kind, options: &ReadOptions) -> Structure {
    let number = |key: Key, value: Option<usize>| {
        value.map(|value| Setting {
            value,
            origin: Origin {
                line: None,
                field: Some(key.option().to_owned()),
            },
        })
    };
    let knots = |key: Key, spec: &Option<KnotSpec>| {
        spec.clone().map(|spec| KnotsSetting {
            spec,
            origin: Origin {
                line: None,
                field: Some(key.option().to_owned()),
            },
            lines: Vec::new(),
        })
    };
    let flag = |key: Key, value: Option<bool>| {
        value.map(|value| Setting {
            value,
            origin: Origin {
                line: None,
                field: Some(key.option().to_owned()),
            },
        })
    };
    if kind.is_surface() {
        // `ReadOptions::check` made sure that --rows and --cols are given for surface kinds.
        let count = |key: Key, value: Option<usize>| {
            number(key, value).unwrap_or(Setting {
                value: 0,
                origin: Origin {
                    line: None,
                    field: Some(key.option().to_owned()),
                },
            })
        };
        Structure::Surface {
            rows: count(Key::Rows, options.rows),
            cols: count(Key::Cols, options.cols),
            degree_u: number(Key::DegreeU, options.degree_u),
            degree_v: number(Key::DegreeV, options.degree_v),
            knots_u: knots(Key::KnotsU, &options.knots_u),
            knots_v: knots(Key::KnotsV, &options.knots_v),
            periodic_u: flag(Key::PeriodicU, options.periodic_u),
            periodic_v: flag(Key::PeriodicV, options.periodic_v),
        }
    } else {
        Structure::Curve {
            degree: number(Key::Degree, options.degree),
            knots: knots(Key::Knots, &options.knots),
            periodic: flag(Key::Periodic, options.periodic),
        }
    }
}

/// Said of a control-point table with a column of fitting data (`parameter`, or `weight` for
/// a kind without weights): the file may be measured points, which `fit` reads.
const FIT_HINT: &str = "; a table of measured points (with a parameter or weight per point) \
                        is fitted by `neutrospline fit FILE`, not evaluated";

/// What a header cell names: a field of the control point, a channel of the interval-valued
/// and bipolar families (index in [`crate::parsed::WIDE_CHANNELS`]), or a spread.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Column {
    Field(Field),
    Channel(usize),
    Spread(SpreadKey),
}

/// The column a header cell names; the message explains an unknown heading.
fn column(heading: &str) -> Result<Column, String> {
    Field::from_name(heading, true)
        .map(Column::Field)
        .or_else(|| wide_channel(heading, true).map(Column::Channel))
        .or_else(|| SpreadKey::from_name(heading, true).map(Column::Spread))
        .ok_or_else(|| {
            let fit = if heading.eq_ignore_ascii_case("parameter") {
                FIT_HINT
            } else {
                ""
            };
            format!(
                "unknown column `{heading}` (known columns: {}){}{fit}",
                Field::known_list(),
                spread_hint(heading)
            )
        })
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod framing_tests;
