//! One schema: the core's serde form of a control point (`neutrospline` feature `serde`) is the
//! control point of the model files, in both directions. A model file whose control points are
//! the core's serialized points reads back to those points, and every control point that the
//! JSON writer writes deserializes with the core's serde to the model's point.

use neutrospline::strategies::{bspline, control_point};
use neutrospline::{AnyCurve, ControlPoint, ControlPolygon};
use neutrospline_io::{parse, to_json_string, Format, Model, ReadOptions, Shape};
use proptest::prelude::*;
use serde_json::Value;

/// The model file of a B-spline curve whose control points are `points`, in the core's form.
fn document<const D: usize>(points: &[ControlPoint<D>], degree: usize, knots: &[f64]) -> String {
    let control_points: Vec<Value> = points
        .iter()
        .map(|p| serde_json::to_value(p).unwrap())
        .collect();
    serde_json::json!({
        "kind": "bspline",
        "degree": degree,
        "knots": knots,
        "control_points": control_points,
    })
    .to_string()
}

/// The control points a JSON model holds, without the file-only keys (`name`, `weight`),
/// deserialized by the core.
fn core_points<const D: usize>(json: &str) -> Vec<ControlPoint<D>> {
    let value: Value = serde_json::from_str(json).unwrap();
    value["control_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let mut p = p.as_object().unwrap().clone();
            p.remove("name");
            p.remove("weight");
            serde_json::from_value(Value::Object(p)).unwrap()
        })
        .collect()
}

fn check<const D: usize>(curve: neutrospline::BSpline<D>) -> Result<(), TestCaseError>
where
    Shape: From<AnyCurve<D>>,
{
    let points = curve.control_points();
    let text = document(&points, curve.degree(), curve.knots().knots());
    let model = parse(
        "core.json",
        Format::Json,
        text.as_bytes(),
        &ReadOptions::default(),
    )
    .map_err(|e| TestCaseError::fail(e.to_string()))?;
    let read = match model.shape() {
        Shape::Curve(c) => c
            .control_rows()
            .iter()
            .map(|row| row[..c.dimension()].to_vec())
            .collect(),
        Shape::Surface(_) => Vec::new(),
    };
    let want: Vec<Vec<f64>> = points.iter().map(|p| p.position.to_vec()).collect();
    prop_assert_eq!(read, want);
    prop_assert_eq!(model.shape(), &Shape::from(AnyCurve::from(curve.clone())));
    // The other way: what the writer writes is the core's form.
    let written = to_json_string(&Model::new(Shape::from(AnyCurve::from(curve))));
    prop_assert_eq!(core_points::<D>(&written), points);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn core_points_are_file_points_2d(curve in bspline::<2>(0..=5)) {
        check(curve)?;
    }

    #[test]
    fn core_points_are_file_points_3d(curve in bspline::<3>(0..=5)) {
        check(curve)?;
    }

    #[test]
    fn one_point_either_way(p in control_point::<3>()) {
        // The key order of the core's form is the writer's: x, y, z, truth, indeterminacy,
        // falsity.
        let text = serde_json::to_string(&p).unwrap();
        let keys = ["\"x\"", "\"y\"", "\"z\"", "\"truth\"", "\"indeterminacy\"", "\"falsity\""];
        let at: Vec<usize> = keys.iter().map(|k| text.find(k).unwrap()).collect();
        prop_assert!(at.windows(2).all(|w| w[0] < w[1]), "{}", text);
    }
}
