//! Regressions found by running the real-file check on files its suite had not seen
//! (`NEUTROSPLINE_REALFILES`, tests/realfiles/README.md): each test holds a minimal file
//! transcribed from the real one, with its source.

use super::*;

fn import(svg: &str) -> Result<Import, ReadError> {
    parse_svg(
        "u.svg",
        svg.as_bytes(),
        &ImportOptions::new(Degrees::new(1.0, 0.0, 0.0).unwrap()),
        &Limits::default(),
    )
}

/// Inkscape's flowed text (`<flowRoot>`, SVG 1.2 draft) in `share/extensions/tests/data/svg/
/// hershey_trivial_input.svg`, `text_types.svg` and `share/examples/flowsample.svg`,
/// `flow-go.svg` (Inkscape 1.2.2): the flowRoot was passed over without a word, text and
/// all. It is text, reported as not a curve; the `<rect>` or `<use>` of its `<flowRegion>`
/// is the frame the text flows in, which no renderer draws, and is not imported. The
/// structure of hershey_trivial_input.svg's flowRoot `A`, with a drawn path beside it.
#[test]
fn svg_flowed_text_is_reported_and_its_frame_not_drawn() {
    let flow = "<flowRoot transform=\"translate(-18.75)\" id=\"A\"><flowRegion \
        id=\"flowRegion23\"><rect id=\"rect25\" width=\"121.08263\" height=\"52.065529\" \
        x=\"182.22934\" y=\"166.4886\"/></flowRegion><flowPara id=\"flowPara27\">Flow\
        </flowPara></flowRoot>";
    let svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"400\" height=\"300\">{flow}\
         <path d=\"M 0 0 L 10 0\"/><defs>{flow}</defs></svg>"
    );
    let read = import(&svg).unwrap();
    assert_eq!(read.models.len(), 1);
    assert_eq!(
        read.report.summary(),
        "imported 1 curve (1 <path>); skipped 1 <flowRoot> (not a curve); not drawn: 1 \
         <flowRoot> in <defs> (definitions never used)"
    );
    // A file of flowed text only (flowsample.svg) has no curve, and says what it holds.
    let only = format!("<svg xmlns=\"http://www.w3.org/2000/svg\">{flow}</svg>");
    assert_eq!(
        import(&only).map(|i| i.models).unwrap_err().to_string(),
        "u.svg: the file has no curve to import (imported no curve; skipped 1 <flowRoot> \
         (not a curve))"
    );
}
