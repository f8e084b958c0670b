//! The report of a surface fit as one JSON object: what `neutrospline fit --surface --report
//! json` prints and what Python's `fit_surface` returns (parsed), defined once here.

use neutrospline::fit::SurfaceFitReport;

/// The report as a JSON object: the curve report's keys, with pairs where a surface has two
/// directions: `control_points` `[m, n]`, `degrees` `[p, q]`, `max_error` and `rms_error` (per
/// channel), `worst_index`, `worst_parameters` `[u, v]`, `worst_distance`,
/// `data_in_every_support`, `two_pass`, `condition_estimate`, `at_bound` (a list of `row`,
/// `col`, `channel`, `bound`), `tolerance` and `tolerance_met` (`null` without a tolerance).
/// A number that is not finite is `null`.
pub fn surface_fit_report_json(report: &SurfaceFitReport) -> String {
    let number = |v: f64| {
        serde_json::Number::from_f64(v).map_or(serde_json::Value::Null, serde_json::Value::Number)
    };
    let channels = |values: &[(&'static str, f64)]| {
        serde_json::Value::Object(
            values
                .iter()
                .map(|(name, v)| ((*name).to_owned(), number(*v)))
                .collect(),
        )
    };
    let n = report.control_points[1];
    let value = serde_json::json!({
        "control_points": report.control_points,
        "degrees": report.degrees,
        "max_error": channels(&report.max_error),
        "rms_error": channels(&report.rms_error),
        "worst_index": report.worst_index,
        "worst_parameters": report.worst_parameters.map(number),
        "worst_distance": number(report.worst_distance),
        "data_in_every_support": report.data_in_every_support,
        "two_pass": report.two_pass,
        "condition_estimate": number(report.condition_estimate),
        "at_bound": report.at_bound.iter().map(|a| serde_json::json!({
            "row": a.index / n,
            "col": a.index % n,
            "channel": a.channel,
            "bound": a.bound,
        })).collect::<Vec<_>>(),
        "tolerance": report.tolerance.map(number),
        "tolerance_met": report.tolerance_met,
    });
    value.to_string()
}
