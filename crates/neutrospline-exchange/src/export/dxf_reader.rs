//! A small reader of the DXF files the exporter writes, for the tests: the group-code / value
//! pairs of the text, the entities of the ENTITIES section, and each SPLINE entity's degree,
//! knots, weights, control points and `NEUTROSPLINE` extended data, every number parsed back
//! with Rust's correctly rounded `f64` parser (so a written number reads back to the last bit).

use crate::dxf_xdata::{self, ModelInfo, XTag};

pub(super) use crate::dxf_import::{groups, Group};

/// An entity: its type (`SPLINE`, `POLYLINE`, `VERTEX`, ...) and its groups after `0 TYPE`,
/// extended data included.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Entity<'a> {
    pub kind: &'a str,
    pub groups: Vec<Group<'a>>,
}

impl<'a> Entity<'a> {
    /// The values of every group with `code` before the extended data, in order.
    pub fn values(&self, code: u16) -> Vec<&'a str> {
        self.groups
            .iter()
            .take_while(|g| g.code != 1001)
            .filter(|g| g.code == code)
            .map(|g| g.value)
            .collect()
    }

    /// The one value of `code`, parsed.
    pub fn one<T: std::str::FromStr>(&self, code: u16) -> T {
        let values = self.values(code);
        assert_eq!(
            values.len(),
            1,
            "{} has {} groups {code}",
            self.kind,
            values.len()
        );
        match values[0].trim().parse() {
            Ok(v) => v,
            Err(_) => panic!(
                "{}: group {code} = `{}` does not parse",
                self.kind, values[0]
            ),
        }
    }

    /// Every value of `code` as a real.
    pub fn reals(&self, code: u16) -> Vec<f64> {
        self.values(code)
            .iter()
            .map(|v| v.parse::<f64>().expect("a real"))
            .collect()
    }

    /// The points of the groups `code`, `code + 10`, `code + 20` (x, y, z), in order.
    pub fn points(&self, code: u16) -> Vec<[f64; 3]> {
        let [x, y, z] = [code, code + 10, code + 20].map(|c| self.reals(c));
        assert!(
            x.len() == y.len() && y.len() == z.len(),
            "{}: ragged points",
            self.kind
        );
        (0..x.len()).map(|k| [x[k], y[k], z[k]]).collect()
    }

    /// The extended data of the application `NEUTROSPLINE`, read back.
    pub fn info(&self) -> Result<ModelInfo, (usize, String)> {
        let start = self
            .groups
            .iter()
            .position(|g| g.code == 1001 && g.value == dxf_xdata::APP)
            .ok_or((
                0,
                format!("{} has no NEUTROSPLINE extended data", self.kind),
            ))?;
        let tags: Vec<XTag<'_>> = self.groups[start + 1..]
            .iter()
            .take_while(|g| g.code != 1001)
            .map(|g| (g.code, g.value, g.line))
            .collect();
        dxf_xdata::read(&tags, self.groups[start].line)
    }
}

/// The entities of the ENTITIES section, in order.
///
/// # Panics
/// If the text has no ENTITIES section or its groups do not parse.
pub(super) fn entities(text: &str) -> Vec<Entity<'_>> {
    let groups = groups(text).expect("DXF groups").0;
    let start = groups
        .windows(2)
        .position(|w| w[0].code == 0 && w[0].value == "SECTION" && w[1].value == "ENTITIES")
        .expect("an ENTITIES section")
        + 2;
    let mut out: Vec<Entity<'_>> = Vec::new();
    for g in &groups[start..] {
        if g.code == 0 {
            if g.value == "ENDSEC" {
                return out;
            }
            out.push(Entity {
                kind: g.value,
                groups: Vec::new(),
            });
        } else {
            out.last_mut()
                .expect("a group after `0 TYPE`")
                .groups
                .push(*g);
        }
    }
    panic!("the ENTITIES section has no ENDSEC")
}

/// What a SPLINE entity holds.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Spline {
    /// Group 70: 4 rational, 8 planar.
    pub flags: i64,
    pub degree: usize,
    pub knots: Vec<f64>,
    /// Empty when the curve is not rational.
    pub weights: Vec<f64>,
    pub control_points: Vec<[f64; 3]>,
    pub info: ModelInfo,
}

impl Spline {
    /// Reads a SPLINE entity, checking that its counts (groups 72 and 73) match its knots and
    /// control points and that group 74 says it has no fit points.
    pub fn read(entity: &Entity<'_>) -> Spline {
        assert_eq!(entity.kind, "SPLINE");
        let spline = Spline {
            flags: entity.one(70),
            degree: entity.one(71),
            knots: entity.reals(40),
            weights: entity.reals(41),
            control_points: entity.points(10),
            info: entity.info().expect("NEUTROSPLINE extended data"),
        };
        assert_eq!(entity.one::<usize>(72), spline.knots.len());
        assert_eq!(entity.one::<usize>(73), spline.control_points.len());
        assert_eq!(entity.one::<usize>(74), 0);
        spline
    }
}
