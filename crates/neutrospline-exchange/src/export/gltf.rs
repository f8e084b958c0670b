//! glTF 2.0: the sampled shape as one mesh with one primitive, a line strip for a curve or
//! indexed triangles with normals for a surface. Attributes (all float32, one buffer view
//! each, 4-byte aligned): `POSITION` (with its exact float32 `min` and `max`), `NORMAL`
//! (surfaces), `COLOR_0` (linear RGB of the viridis colour of the chosen value, so that a
//! viewer's sRGB output shows the figures' colours) and the degrees as the application-specific
//! attributes `_TRUTH`, `_INDETERMINACY`, `_FALSITY` (for an interval-valued or bipolar
//! family, its channels instead, each as `_` and its name in capitals: `_TRUTH_LOWER`, ...,
//! `_NEGATIVE_TRUTH`, ...). `asset.extras` holds the model's name, description, kind and
//! membership rule and the colouring.
//!
//! Model coordinates are z-up; glTF is y-up, so a 3-D shape's node turns z up (a rotation of
//! -90 degrees about x) and the vertices keep the model's coordinates. A plane curve lies in the
//! x-y plane, facing the viewer, unturned.

use serde_json::{json, Map, Value};

use super::{ColorBy, Samples};
use neutrospline_io::Model;

/// Component type FLOAT and UNSIGNED_INT; buffer view targets.
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
/// Primitive modes.
const POINTS: u32 = 0;
const LINE_STRIP: u32 = 3;
const TRIANGLES: u32 = 4;
/// The rotation of -90 degrees about x (z up to y up), as a unit quaternion `[x, y, z, w]`.
const Z_UP_TO_Y_UP: [f64; 4] = [
    -std::f64::consts::FRAC_1_SQRT_2,
    0.0,
    0.0,
    std::f64::consts::FRAC_1_SQRT_2,
];

/// The binary buffer, its buffer views and accessors being built.
#[derive(Default)]
struct Buffer {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl Buffer {
    /// Appends `bytes` as a new buffer view (4-byte aligned) and returns its index.
    fn view(&mut self, bytes: &[u8], target: u32) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.views.push(json!({
            "buffer": 0,
            "byteOffset": self.bin.len(),
            "byteLength": bytes.len(),
            "target": target,
        }));
        self.bin.extend_from_slice(bytes);
        self.views.len() - 1
    }

    /// A float32 accessor of `components` per element (1: SCALAR, 3: VEC3), with `min` and
    /// `max` per component; returns its index.
    fn floats(&mut self, data: &[f32], components: usize) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|v| v.to_le_bytes()).collect();
        let view = self.view(&bytes, ARRAY_BUFFER);
        let mut min = vec![f32::INFINITY; components];
        let mut max = vec![f32::NEG_INFINITY; components];
        for element in data.chunks_exact(components) {
            for (k, &v) in element.iter().enumerate() {
                min[k] = min[k].min(v);
                max[k] = max[k].max(v);
            }
        }
        let widen = |v: Vec<f32>| v.into_iter().map(f64::from).collect::<Vec<f64>>();
        self.accessors.push(json!({
            "bufferView": view,
            "componentType": FLOAT,
            "count": data.len() / components,
            "type": if components == 3 { "VEC3" } else { "SCALAR" },
            "min": widen(min),
            "max": widen(max),
        }));
        self.accessors.len() - 1
    }

    /// An accessor of triangle indices.
    fn indices(&mut self, triangles: &[[u32; 3]]) -> usize {
        let bytes: Vec<u8> = triangles
            .iter()
            .flatten()
            .flat_map(|k| k.to_le_bytes())
            .collect();
        let view = self.view(&bytes, ELEMENT_ARRAY_BUFFER);
        self.accessors.push(json!({
            "bufferView": view,
            "componentType": UNSIGNED_INT,
            "count": triangles.len() * 3,
            "type": "SCALAR",
        }));
        self.accessors.len() - 1
    }
}

/// Three `f64` per point as float32.
fn vec3(points: &[[f64; 3]]) -> Vec<f32> {
    points.iter().flatten().map(|&v| v as f32).collect()
}

/// The glTF document (without its buffer's `uri`) and the binary buffer.
fn build(model: &Model, samples: &Samples, by: ColorBy) -> (Map<String, Value>, Vec<u8>) {
    let mut buffer = Buffer::default();
    let mut attributes = Map::new();
    attributes.insert(
        "POSITION".into(),
        buffer.floats(&vec3(&samples.positions), 3).into(),
    );
    if let Some(normals) = &samples.normals {
        attributes.insert("NORMAL".into(), buffer.floats(&vec3(normals), 3).into());
    }
    let colors: Vec<f32> = samples
        .colors(by)
        .iter()
        .flatten()
        .map(|&c| neutrospline::color::srgb_to_linear(c) as f32)
        .collect();
    attributes.insert("COLOR_0".into(), buffer.floats(&colors, 3).into());
    // `_TRUTH`, `_INDETERMINACY`, `_FALSITY`, or a wide family's channels (`_TRUTH_LOWER`,
    // ..., `_NEGATIVE_TRUTH`, ...).
    let (names, rows) = samples.value_columns();
    for (k, name) in names.into_iter().enumerate() {
        let values: Vec<f32> = rows.iter().map(|row| row[k] as f32).collect();
        attributes.insert(
            format!("_{}", name.to_ascii_uppercase()),
            buffer.floats(&values, 1).into(),
        );
    }
    let (mode, indices) = match &samples.triangles {
        None => (LINE_STRIP, None),
        // A surface collapsed to a line or a point has no triangle: its points.
        Some(t) if t.is_empty() => (POINTS, None),
        Some(t) => (TRIANGLES, Some(buffer.indices(t))),
    };
    let mut primitive = json!({ "attributes": attributes, "material": 0, "mode": mode });
    if let Some(indices) = indices {
        primitive["indices"] = indices.into();
    }
    let label = model.name().unwrap_or(model.kind().name());
    let mut extras = Map::new();
    if let Some(name) = model.name() {
        extras.insert("name".into(), name.into());
    }
    if let Some(description) = model.description() {
        extras.insert("description".into(), description.into());
    }
    extras.insert("kind".into(), model.kind().name().into());
    extras.insert("membership".into(), model.membership().to_string().into());
    extras.insert("color_by".into(), by.name().into());
    let mut node = json!({ "name": label, "mesh": 0 });
    if samples.dimension == 3 {
        node["rotation"] = json!(Z_UP_TO_Y_UP);
    }
    let document = json!({
        "asset": {
            "version": "2.0",
            "generator": concat!("neutrospline-exchange ", env!("CARGO_PKG_VERSION")),
            "extras": extras,
        },
        "scene": 0,
        "scenes": [{ "name": label, "nodes": [0] }],
        "nodes": [node],
        "meshes": [{ "name": label, "primitives": [primitive] }],
        "materials": [{
            "name": format!("vertex colours: viridis of {by}"),
            "pbrMetallicRoughness": {
                "baseColorFactor": [1.0, 1.0, 1.0, 1.0],
                "metallicFactor": 0.0,
                "roughnessFactor": 0.9,
            },
            "doubleSided": true,
        }],
        "accessors": buffer.accessors,
        "bufferViews": buffer.views,
        "buffers": [{ "byteLength": buffer.bin.len() }],
    });
    let Value::Object(map) = document else {
        unreachable!("json! of an object literal is an object")
    };
    (map, buffer.bin)
}

/// Binary glTF: the 12-byte header (`glTF`, version 2, total length), the JSON chunk padded
/// with spaces and the BIN chunk padded with zeros, each to a multiple of 4 bytes.
pub(super) fn glb(model: &Model, samples: &Samples, by: ColorBy) -> Vec<u8> {
    let (document, mut bin) = build(model, samples, by);
    let mut json = Value::Object(document).to_string().into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    let u32le = |v: usize| u32::try_from(v).unwrap_or(u32::MAX).to_le_bytes();
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&u32le(total));
    out.extend_from_slice(&u32le(json.len()));
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(&u32le(bin.len()));
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}

/// glTF JSON with the buffer embedded as a base64 data URI.
pub(super) fn gltf(model: &Model, samples: &Samples, by: ColorBy) -> String {
    let (mut document, bin) = build(model, samples, by);
    let uri = format!("data:application/octet-stream;base64,{}", base64(&bin));
    document["buffers"][0]["uri"] = uri.into();
    let mut text = serde_json::to_string_pretty(&Value::Object(document)).unwrap_or_default();
    text.push('\n');
    text
}

/// Standard base64 (RFC 4648, with padding).
pub(super) fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * k)) as usize & 63]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_of_rfc_4648_vectors() {
        for (input, output) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(input.as_bytes()), output);
        }
    }

    #[test]
    fn quaternion_is_unit() {
        let n: f64 = Z_UP_TO_Y_UP.iter().map(|q| q * q).sum();
        assert!((n - 1.0).abs() < 1e-15);
    }
}
