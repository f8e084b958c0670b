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

/// A surface fit whose condition estimate exceeds this is warned of: about 1e-6 of double
/// precision is left to its control values.
pub const ILL_CONDITIONED: f64 = 1e10;

/// The warning of a surface fit to `data` (the name shown) whose least-squares system is
/// nearly singular (condition estimate above [`ILL_CONDITIONED`]): where the data barely reach,
/// control points are set by rounding. `None` for a well-conditioned fit. The command line
/// prints it after `warning: `; Python raises it as a `RuntimeWarning`.
pub fn surface_fit_warning(data: &str, report: &SurfaceFitReport) -> Option<String> {
    (report.condition_estimate > ILL_CONDITIONED).then(|| {
        format!(
            "{data}: the least-squares system is nearly singular (condition estimate {:.1e}): \
             parts of the parameter domain have too little data to determine their control \
             points, which are then set by rounding. Give smoothing (--smoothing LAMBDA: the \
             thin-plate energy then determines them), fewer control points, or data that \
             covers the domain",
            report.condition_estimate
        )
    })
}
