//! The exports read back: the DXF SPLINE of every example curve gives the model's degree,
//! knots, weights, control points and degrees to the last bit; glTF, PLY and OBJ files hold
//! exactly the samples, with the counts and layouts their formats prescribe.

use std::path::PathBuf;

use neutrospline::{
    AnyCurve, BSpline, ControlPoint, ControlPolygon, Degrees, Evaluate, KnotVector, Nurbs,
};
use serde_json::Value;

use super::dxf_reader::{entities, groups, Spline};
use super::{export, export_file, ColorBy, ExportError, ExportFormat, ExportOptions, Samples};
use neutrospline_io::{load, Model, ReadOptions, Shape};

fn example(name: &str) -> Model {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    load(&path, &ReadOptions::default()).expect("an example model")
}

fn options(samples: Option<usize>, color_by: ColorBy) -> ExportOptions {
    ExportOptions::new()
        .with_samples(samples)
        .with_color_by(color_by)
}

fn bits(values: &[f64]) -> Vec<u64> {
    values.iter().map(|v| v.to_bits()).collect()
}

/// The curve a SPLINE entity describes, rebuilt with the degrees of its extended data.
fn rebuilt<const D: usize>(spline: &Spline) -> AnyCurve<D> {
    let points: Vec<ControlPoint<D>> = spline
        .control_points
        .iter()
        .zip(&spline.info.degrees)
        .map(|(p, d)| ControlPoint::new(p[..D].try_into().unwrap(), *d))
        .collect();
    let knots = KnotVector::new(spline.knots.clone(), spline.degree, points.len()).unwrap();
    if spline.weights.is_empty() {
        AnyCurve::BSpline(BSpline::new(points, knots).unwrap())
    } else {
        AnyCurve::Nurbs(Nurbs::new(points, spline.weights.clone(), knots).unwrap())
    }
}

/// Checks the SPLINE of `curve` against it; returns the largest distance between the curve
/// and the rebuilt spline at 101 parameters (0 for B-spline and NURBS models, whose SPLINE is
/// the same curve evaluated by the same routine).
fn check_spline<const D: usize>(model: &Model, curve: &AnyCurve<D>, spline: &Spline) -> f64 {
    assert_eq!(spline.degree, curve.degree());
    let n = curve.len();
    match curve {
        AnyCurve::Bezier(_) => {
            let mut expected = vec![0.0; n];
            expected.extend(vec![1.0; n]);
            assert_eq!(bits(&spline.knots), bits(&expected));
        }
        AnyCurve::BSpline(c) => assert_eq!(bits(&spline.knots), bits(c.knots().knots())),
        AnyCurve::Nurbs(c) => assert_eq!(bits(&spline.knots), bits(c.knots().knots())),
    }
    assert_eq!(bits(&spline.weights), bits(curve.weights().unwrap_or(&[])));
    let rational = if curve.weights().is_some() { 4 } else { 0 };
    let planar = if D == 2 { 8 } else { 0 };
    assert_eq!(spline.flags, rational | planar);
    let points = curve.control_points();
    assert_eq!(spline.control_points.len(), n);
    for (read, p) in spline.control_points.iter().zip(&points) {
        assert_eq!(bits(&read[..D]), bits(&p.position));
        if D == 2 {
            assert_eq!(read[2].to_bits(), 0.0f64.to_bits());
        }
    }
    let info = &spline.info;
    assert_eq!(info.kind, model.kind());
    assert_eq!(info.dimension, D);
    assert_eq!(info.membership, model.membership());
    assert_eq!(info.name.as_deref(), model.name());
    assert_eq!(info.description.as_deref(), model.description());
    let degree_bits =
        |d: &[Degrees]| -> Vec<u64> { d.iter().flat_map(|d| bits(&d.to_array())).collect() };
    assert_eq!(
        degree_bits(&info.degrees),
        degree_bits(&model.shape().control_degrees())
    );
    assert_eq!(info.point_names, model.point_names());
    let again = rebuilt::<D>(spline);
    let mut worst: f64 = 0.0;
    for k in 0..=100 {
        let t = neutrospline::uniform_parameter(k, 101, curve.domain());
        let (a, b) = (curve.evaluate(t).unwrap(), again.evaluate(t).unwrap());
        for axis in 0..D {
            worst = worst.max((a.position[axis] - b.position[axis]).abs());
        }
        for (x, y) in a.degrees.to_array().into_iter().zip(b.degrees.to_array()) {
            worst = worst.max((x - y).abs());
        }
    }
    worst
}

#[test]
fn dxf_spline_of_every_example_curve_reads_back_exactly() {
    for (file, exact) in [
        ("example1.toml", false),
        ("helix3d.toml", false),
        ("bspline.toml", true),
        ("nurbs-circle.toml", true),
    ] {
        let model = example(file);
        let bytes = export(&model, ExportFormat::Dxf, &ExportOptions::default()).unwrap();
        let text = String::from_utf8(bytes).unwrap();
        assert!(text.is_ascii(), "{file}: a DXF R2004 file is ASCII");
        let all = entities(&text);
        assert_eq!(all.len(), 1, "{file}: one entity");
        let spline = Spline::read(&all[0]);
        let worst = match model.shape() {
            Shape::Curve(c) => {
                neutrospline::on_dimension!(c, c => check_spline(&model, c, &spline))
            }
            Shape::Surface(_) => unreachable!("a curve example"),
        };
        if exact {
            assert_eq!(worst, 0.0, "{file}");
        } else {
            // A Bezier curve by de Casteljau, its SPLINE by de Boor: the same curve to rounding.
            assert!(worst < 1e-14, "{file}: {worst}");
        }
    }
}

#[test]
fn dxf_example1_spline_entity() {
    let model = example("example1.toml");
    let text =
        String::from_utf8(export(&model, ExportFormat::Dxf, &ExportOptions::default()).unwrap())
            .unwrap();
    let spline = &entities(&text)[0];
    assert_eq!(spline.values(100), ["AcDbEntity", "AcDbSpline"]);
    assert_eq!(spline.one::<u16>(71), 3);
    assert_eq!(spline.reals(40), [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
    assert_eq!(
        spline.points(10),
        [
            [1.0, 3.0, 0.0],
            [3.0, 6.0, 0.0],
            [6.0, 2.0, 0.0],
            [9.0, 5.0, 0.0]
        ]
    );
    assert_eq!(spline.points(210), [[0.0, 0.0, 1.0]]);
    // The extended data, value by value: C3's indeterminacy is Table 1's 0.4.
    let xdata: Vec<(u16, &str)> = spline
        .groups
        .iter()
        .skip_while(|g| g.code != 1001)
        .map(|g| (g.code, g.value))
        .collect();
    assert_eq!(
        xdata[..8],
        [
            (1001, "NEUTROSPLINE"),
            (1000, "neutrospline 1"),
            (1000, "kind"),
            (1000, "bezier"),
            (1000, "dimension"),
            (1070, "2"),
            (1000, "membership"),
            (1000, "neutrosophic"),
        ]
    );
    let degrees = xdata.iter().position(|&x| x == (1000, "degrees")).unwrap();
    assert_eq!(xdata[degrees + 1], (1071, "4"));
    let values: Vec<&str> = xdata[degrees + 2..degrees + 14]
        .iter()
        .map(|x| x.1)
        .collect();
    assert_eq!(
        values,
        ["0.3", "0.6", "0.1", "0.8", "0.1", "0.1", "0.7", "0.1", "0.2", "0.2", "0.4", "0.4"]
    );
    // Handles are unique, and $HANDSEED is past the last of them.
    let all = groups(&text).unwrap().0;
    let mut handles: Vec<u32> = all
        .iter()
        .filter(|g| g.code == 5 || g.code == 105)
        .map(|g| u32::from_str_radix(g.value, 16).unwrap())
        .collect();
    let seed = handles.remove(0); // $HANDSEED, the first group 5 of the header
    let count = handles.len();
    handles.sort_unstable();
    handles.dedup();
    assert_eq!(handles.len(), count, "unique handles");
    assert_eq!(seed, handles[count - 1] + 1);
    assert!(text.starts_with("  0\nSECTION\n  2\nHEADER\n  9\n$ACADVER\n  1\nAC1018\n"));
    assert!(text.ends_with("  0\nEOF\n"));
}

#[test]
fn dxf_mesh_of_a_surface() {
    let model = example("surface.toml");
    let opts = options(Some(5), ColorBy::Falsity).with_mesh(true);
    let text = String::from_utf8(export(&model, ExportFormat::Dxf, &opts).unwrap()).unwrap();
    let samples = Samples::of(model.shape(), Some(5)).unwrap();
    let triangles = samples.triangles.as_ref().unwrap();
    assert_eq!(triangles.len(), 32);
    let all = entities(&text);
    // POLYLINE, 25 vertices, 32 face records, SEQEND.
    assert_eq!(all.len(), 1 + 25 + 32 + 1);
    let mesh = &all[0];
    assert_eq!(
        (
            mesh.kind,
            mesh.one::<i64>(70),
            mesh.one::<usize>(71),
            mesh.one::<usize>(72)
        ),
        ("POLYLINE", 64, 25, 32)
    );
    let info = mesh.info().unwrap();
    assert_eq!(
        (info.kind, info.name.as_deref()),
        (model.kind(), Some("bicubic hill"))
    );
    // The mesh's vertices are the samples in the order the triangles first use them.
    let mut order: Vec<u32> = Vec::new();
    for &k in triangles.iter().flatten() {
        if !order.contains(&k) {
            order.push(k);
        }
    }
    for (vertex, &k) in all[1..26].iter().zip(&order) {
        let k = k as usize;
        assert_eq!((vertex.kind, vertex.one::<i64>(70)), ("VERTEX", 192));
        assert_eq!(bits(&vertex.points(10)[0]), bits(&samples.positions[k]));
        let groups = &vertex.groups;
        let degrees: Vec<f64> = groups
            .iter()
            .filter(|g| g.code == 1040)
            .map(|g| g.value.parse().unwrap())
            .collect();
        assert_eq!(bits(&degrees), bits(&samples.degrees[k].to_array()));
    }
    for (face, triangle) in all[26..58].iter().zip(triangles) {
        assert_eq!((face.kind, face.one::<i64>(70)), ("VERTEX", 128));
        let corners = [71, 72, 73].map(|c| order[face.one::<usize>(c) - 1]);
        assert_eq!(corners, *triangle);
        let mean = triangle
            .iter()
            .map(|&k| samples.degrees[k as usize].falsity())
            .sum::<f64>()
            / 3.0;
        let [r, g, b] = neutrospline::color::viridis(mean);
        assert_eq!(
            face.one::<i64>(420),
            (i64::from(r) << 16) | (i64::from(g) << 8) | i64::from(b)
        );
    }
    assert_eq!(all[58].kind, "SEQEND");
}

/// The JSON chunk and the BIN chunk of a GLB file, after checking its header.
fn glb_chunks(bytes: &[u8]) -> (Value, Vec<u8>) {
    let u32_at = |k: usize| u32::from_le_bytes(bytes[k..k + 4].try_into().unwrap()) as usize;
    assert_eq!(&bytes[..4], b"glTF");
    assert_eq!(u32_at(4), 2);
    assert_eq!(u32_at(8), bytes.len());
    let json_length = u32_at(12);
    assert_eq!(&bytes[16..20], b"JSON");
    assert_eq!(json_length % 4, 0);
    let json: Value = serde_json::from_slice(&bytes[20..20 + json_length]).unwrap();
    let bin_start = 20 + json_length;
    let bin_length = u32_at(bin_start);
    assert_eq!(&bytes[bin_start + 4..bin_start + 8], b"BIN\0");
    assert_eq!(bin_start + 8 + bin_length, bytes.len());
    (json, bytes[bin_start + 8..].to_vec())
}

/// The float32 values of an accessor.
fn floats(json: &Value, bin: &[u8], accessor: usize) -> Vec<f32> {
    let a = &json["accessors"][accessor];
    let view = &json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
    let start = view["byteOffset"].as_u64().unwrap() as usize;
    let length = view["byteLength"].as_u64().unwrap() as usize;
    assert_eq!(start % 4, 0);
    assert_eq!(a["componentType"], 5126);
    bin[start..start + length]
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
        .collect()
}

#[test]
fn glb_of_a_curve_holds_the_samples_and_degrees() {
    let model = example("example1.toml");
    let bytes = export(
        &model,
        ExportFormat::Glb,
        &options(Some(11), ColorBy::Score),
    )
    .unwrap();
    let (json, bin) = glb_chunks(&bytes);
    assert_eq!(json["asset"]["version"], "2.0");
    assert_eq!(json["asset"]["extras"]["name"], "Example 1");
    assert_eq!(json["asset"]["extras"]["color_by"], "score");
    assert_eq!(json["asset"]["extras"]["kind"], "bezier");
    assert_eq!(
        json["buffers"][0]["byteLength"].as_u64().unwrap() as usize,
        bin.len()
    );
    assert!(json["buffers"][0].get("uri").is_none());
    // A plane curve is not turned.
    assert!(json["nodes"][0].get("rotation").is_none());
    let primitive = &json["meshes"][0]["primitives"][0];
    assert_eq!(primitive["mode"], 3);
    assert!(primitive.get("indices").is_none());
    let attribute = |name: &str| primitive["attributes"][name].as_u64().unwrap() as usize;
    let samples = Samples::of(model.shape(), Some(11)).unwrap();
    let positions = floats(&json, &bin, attribute("POSITION"));
    assert_eq!(positions.len(), 33);
    // t = 0.5 is the sixth sample: (4.625, 4) exactly.
    assert_eq!(positions[15..18], [4.625, 4.0, 0.0]);
    let accessor = &json["accessors"][attribute("POSITION")];
    assert_eq!(accessor["count"], 11);
    assert_eq!(accessor["min"], serde_json::json!([1.0, 3.0, 0.0]));
    assert_eq!(accessor["max"][0], 9.0);
    for (k, name) in ["_TRUTH", "_INDETERMINACY", "_FALSITY"]
        .into_iter()
        .enumerate()
    {
        let values = floats(&json, &bin, attribute(name));
        let expected: Vec<f32> = samples
            .degrees
            .iter()
            .map(|d| d.to_array()[k] as f32)
            .collect();
        assert_eq!(values, expected, "{name}");
    }
    assert_eq!(floats(&json, &bin, attribute("_TRUTH"))[5], 0.625);
    let colors = floats(&json, &bin, attribute("COLOR_0"));
    let score = (2.0 + 0.625 - 0.2 - 0.175) / 3.0;
    let expected =
        neutrospline::color::viridis(score).map(|c| neutrospline::color::srgb_to_linear(c) as f32);
    assert_eq!(colors[15..18], expected);
}

#[test]
fn glb_of_a_surface_is_a_triangle_mesh_with_unit_normals() {
    let model = example("surface.toml");
    let bytes = export(&model, ExportFormat::Glb, &options(Some(6), ColorBy::Truth)).unwrap();
    let (json, bin) = glb_chunks(&bytes);
    let primitive = &json["meshes"][0]["primitives"][0];
    assert_eq!(primitive["mode"], 4);
    let indices = &json["accessors"][primitive["indices"].as_u64().unwrap() as usize];
    // A 6 x 6 grid: 25 cells, 50 triangles.
    assert_eq!(
        (indices["count"].as_u64(), indices["componentType"].as_u64()),
        (Some(150), Some(5125))
    );
    let normals = floats(
        &json,
        &bin,
        primitive["attributes"]["NORMAL"].as_u64().unwrap() as usize,
    );
    assert_eq!(normals.len(), 3 * 36);
    for n in normals.chunks_exact(3) {
        let length = n
            .iter()
            .map(|&x| f64::from(x) * f64::from(x))
            .sum::<f64>()
            .sqrt();
        assert!((length - 1.0).abs() < 1e-6);
    }
    // z up in the model, y up in glTF: the node turns -90 degrees about x.
    let rotation = &json["nodes"][0]["rotation"];
    assert_eq!(
        rotation[0].as_f64().unwrap(),
        -std::f64::consts::FRAC_1_SQRT_2
    );
    // The .gltf form: the same document, the same buffer as a data URI.
    let text = String::from_utf8(
        export(
            &model,
            ExportFormat::Gltf,
            &options(Some(6), ColorBy::Truth),
        )
        .unwrap(),
    )
    .unwrap();
    let gltf: Value = serde_json::from_str(&text).unwrap();
    let uri = gltf["buffers"][0]["uri"].as_str().unwrap();
    let encoded = uri
        .strip_prefix("data:application/octet-stream;base64,")
        .unwrap();
    let mut padded = bin.clone();
    padded.truncate(json["buffers"][0]["byteLength"].as_u64().unwrap() as usize);
    assert_eq!(encoded, super::gltf::base64(&padded));
    assert_eq!(gltf["accessors"], json["accessors"]);
    assert_eq!(gltf["meshes"], json["meshes"]);
}

/// The header lines of a PLY file and the bytes after `end_header\n`.
fn ply_parts(bytes: &[u8]) -> (Vec<String>, &[u8]) {
    let end = bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .unwrap()
        + 11;
    let header = std::str::from_utf8(&bytes[..end]).unwrap();
    (header.lines().map(str::to_owned).collect(), &bytes[end..])
}

#[test]
fn ply_binary_of_a_curve() {
    let model = example("helix3d.toml");
    let bytes = export(
        &model,
        ExportFormat::Ply,
        &options(Some(4), ColorBy::Indeterminacy),
    )
    .unwrap();
    let (header, body) = ply_parts(&bytes);
    assert_eq!(header[..2], ["ply", "format binary_little_endian 1.0"]);
    assert_eq!(
        header[2],
        "comment neutrospline export of a bezier \"helix quarter turn\""
    );
    let declarations: Vec<&str> = header
        .iter()
        .map(String::as_str)
        .filter(|l| !l.starts_with("comment"))
        .skip(2)
        .collect();
    assert_eq!(
        declarations,
        [
            "element vertex 4",
            "property double x",
            "property double y",
            "property double z",
            "property uchar red",
            "property uchar green",
            "property uchar blue",
            "property double truth",
            "property double indeterminacy",
            "property double falsity",
            "element edge 3",
            "property uint vertex1",
            "property uint vertex2",
            "end_header",
        ]
    );
    // 4 vertices of 3 + 3 doubles and 3 bytes, 3 edges of two 32-bit indices.
    assert_eq!(body.len(), 4 * 51 + 3 * 8);
    let samples = Samples::of(model.shape(), Some(4)).unwrap();
    let colors = samples.colors(ColorBy::Indeterminacy);
    let double = |k: usize| f64::from_le_bytes(body[k..k + 8].try_into().unwrap());
    for v in 0..4 {
        let row = 51 * v;
        assert_eq!(
            bits(&[double(row), double(row + 8), double(row + 16)]),
            bits(&samples.positions[v])
        );
        assert_eq!(body[row + 24..row + 27], colors[v]);
        let degrees = [double(row + 27), double(row + 35), double(row + 43)];
        assert_eq!(bits(&degrees), bits(&samples.degrees[v].to_array()));
    }
    let edges: Vec<u32> = body[204..]
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes(c.try_into().unwrap()))
        .collect();
    assert_eq!(edges, [0, 1, 1, 2, 2, 3]);
    // The last sample is H3, with its degrees exactly.
    assert_eq!(samples.positions[3], [0.0, 1.0, 0.75]);
    assert_eq!(samples.degrees[3].to_array(), [0.1, 0.2, 0.8]);
}

#[test]
fn ply_ascii_of_a_surface() {
    let model = example("surface.toml");
    let opts = options(Some(3), ColorBy::Truth).with_ascii(true);
    let text = String::from_utf8(export(&model, ExportFormat::Ply, &opts).unwrap()).unwrap();
    let (header, body) = ply_parts(text.as_bytes());
    assert_eq!(header[1], "format ascii 1.0");
    assert!(header.contains(&"element vertex 9".to_owned()));
    assert!(header.contains(&"property double nz".to_owned()));
    assert!(header.contains(&"element face 8".to_owned()));
    assert!(header.contains(&"property list uchar uint vertex_indices".to_owned()));
    let samples = Samples::of(model.shape(), Some(3)).unwrap();
    let lines: Vec<&str> = std::str::from_utf8(body).unwrap().lines().collect();
    assert_eq!(lines.len(), 9 + 8);
    for (k, line) in lines[..9].iter().enumerate() {
        let v: Vec<f64> = line.split(' ').map(|x| x.parse().unwrap()).collect();
        assert_eq!(v.len(), 12);
        assert_eq!(bits(&v[..3]), bits(&samples.positions[k]));
        assert_eq!(bits(&v[3..6]), bits(&samples.normals.as_ref().unwrap()[k]));
        assert_eq!(v[6..9], samples.colors(ColorBy::Truth)[k].map(f64::from));
        assert_eq!(bits(&v[9..]), bits(&samples.degrees[k].to_array()));
    }
    // The centre of the hill, S(0.5, 0.5): the heights blended with (1, 3, 3, 1) / 8 along
    // each row (0.375, 1.625, 1.4375, 0.375), then across them: 9.9375 / 8.
    assert_eq!(
        lines[4].split(' ').take(3).collect::<Vec<_>>(),
        ["1.5", "1.5", "1.2421875"]
    );
    for (line, t) in lines[9..].iter().zip(samples.triangles.as_ref().unwrap()) {
        assert_eq!(*line, format!("3 {} {} {}", t[0], t[1], t[2]));
    }
}

#[test]
fn obj_of_a_curve_and_a_surface() {
    let model = example("bspline.toml");
    let text = String::from_utf8(
        export(
            &model,
            ExportFormat::Obj,
            &options(Some(130), ColorBy::Truth),
        )
        .unwrap(),
    )
    .unwrap();
    let samples = Samples::of(model.shape(), Some(130)).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0],
        "# neutrospline export of a bspline \"cubic B-spline\""
    );
    assert!(lines.contains(&"o cubic B-spline"));
    let vertices: Vec<&str> = lines
        .iter()
        .copied()
        .filter(|l| l.starts_with("v "))
        .collect();
    assert_eq!(vertices.len(), 130);
    assert_eq!(vertices[0], "v 0 0 0 0.741176 0.87451 0.14902");
    assert_eq!(neutrospline::color::viridis(0.9), [189, 223, 38]);
    // 130 points in lines of at most 64 vertices sharing their ends: 1-64, 64-127, 127-130.
    let polylines: Vec<&str> = lines
        .iter()
        .copied()
        .filter(|l| l.starts_with("l "))
        .collect();
    assert_eq!(polylines.len(), 3);
    assert!(polylines[1].starts_with("l 64 65 "));
    assert_eq!(polylines[2], "l 127 128 129 130");
    let degrees: Vec<[f64; 3]> = lines
        .iter()
        .filter_map(|l| l.strip_prefix("#deg "))
        .map(|l| {
            let v: Vec<f64> = l.split(' ').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    assert_eq!(
        degrees,
        samples
            .degrees
            .iter()
            .map(Degrees::to_array)
            .collect::<Vec<_>>()
    );

    let model = example("nurbs-surface.json");
    let text = String::from_utf8(
        export(&model, ExportFormat::Obj, &options(Some(4), ColorBy::Truth)).unwrap(),
    )
    .unwrap();
    let count = |prefix: &str| text.lines().filter(|l| l.starts_with(prefix)).count();
    assert_eq!(
        (
            count("v "),
            count("vn "),
            count("f "),
            count("l "),
            count("#deg ")
        ),
        (16, 16, 18, 0, 16)
    );
    assert!(text.lines().any(|l| l == "f 1//1 5//5 6//6"));
}

#[test]
fn export_errors_name_the_option_and_the_rule() {
    let curve = example("example1.toml");
    let surface = example("surface.toml");
    let message = |model: &Model, format, opts: &ExportOptions| {
        export(model, format, opts).unwrap_err().to_string()
    };
    let ascii = ExportOptions::new().with_ascii(true);
    assert_eq!(
        message(&curve, ExportFormat::Obj, &ascii),
        "--ascii applies to PLY files only (the output is OBJ)"
    );
    let mesh = ExportOptions::new().with_mesh(true);
    assert_eq!(
        message(&surface, ExportFormat::Glb, &mesh),
        "--mesh applies to DXF files only (GLB holds surfaces as meshes anyway)"
    );
    assert_eq!(
        message(&curve, ExportFormat::Dxf, &mesh),
        "--mesh applies to surfaces only (a curve is written as an exact SPLINE entity)"
    );
    assert_eq!(
        message(
            &curve,
            ExportFormat::Dxf,
            &options(Some(10), ColorBy::Truth)
        ),
        "--samples does not apply to a DXF SPLINE, which is exact (it applies to --mesh)"
    );
    assert_eq!(
        message(&surface, ExportFormat::Dxf, &ExportOptions::default()),
        "a bezier-surface cannot be a DXF SPLINE (a SPLINE entity is a curve): export it as a mesh with --mesh (a POLYFACE mesh), or to .glb, .gltf, .ply or .obj"
    );
    assert_eq!(
        message(&curve, ExportFormat::Ply, &options(Some(1), ColorBy::Truth)),
        "--samples 1 is out of range (2 to 10000000 along a curve)"
    );
    assert_eq!(
        message(
            &surface,
            ExportFormat::Ply,
            &options(Some(4097), ColorBy::Truth)
        ),
        "--samples 4097 is out of range (2 to 4096 per direction of a surface)"
    );
    assert!(
        export(&curve, ExportFormat::Ply, &options(Some(1), ColorBy::Truth))
            .unwrap_err()
            .is_usage()
    );
    assert!(
        !export(&surface, ExportFormat::Dxf, &ExportOptions::default())
            .unwrap_err()
            .is_usage()
    );
}

#[test]
fn export_file_replaces_whole_files_only() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("hill.dxf");
    std::fs::write(&target, "old").unwrap();
    let surface = example("surface.toml");
    let error = export_file(&surface, &target, &ExportOptions::default()).unwrap_err();
    assert!(matches!(error, ExportError::SurfaceNeedsMesh { .. }));
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "old");
    let mesh = ExportOptions::new().with_mesh(true);
    export_file(&surface, &target, &mesh).unwrap();
    assert_eq!(
        std::fs::read(&target).unwrap(),
        export(&surface, ExportFormat::Dxf, &mesh).unwrap()
    );
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["hill.dxf"]);
    let error = export_file(&surface, dir.path().join("hill.stl"), &mesh).unwrap_err();
    assert!(error.is_usage());
    let error = export_file(
        &surface,
        dir.path().join("missing/hill.ply"),
        &ExportOptions::default(),
    )
    .unwrap_err();
    assert!(
        error.to_string().starts_with(&format!(
            "{}: cannot write: ",
            dir.path().join("missing/hill.ply").display()
        )),
        "{error}"
    );
}
