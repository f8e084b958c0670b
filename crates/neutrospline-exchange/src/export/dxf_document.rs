//! The frame of a DXF R2004 (AC1018, the first version with true colours, which the faces of
//! a mesh use) document around its entities: the HEADER, the tables every reader of DXF R2000
//! and later expects (VPORT `*ACTIVE`, the line types ByBlock, ByLayer and
//! Continuous, layer `0`, text and dimension style `Standard`, the application IDs `ACAD` and
//! `NEUTROSPLINE`, the block records of model and paper space), the two layout blocks, the
//! ENTITIES section and the OBJECTS section with its root dictionary. Every object has a
//! handle (group code 5, 105 for a DIMSTYLE) and its owner's handle (330); `$HANDSEED` is one
//! past the last.

use std::fmt::Write as _;

use crate::dxf_xdata::{XValue, APP};
use neutrospline_io::push_number;

/// DXF text being written: one group code (right-aligned in three columns, as AutoCAD writes
/// it) and one value per line, with the next free handle.
pub(super) struct Tags {
    out: String,
    next_handle: u32,
}

impl Tags {
    fn new(first_handle: u32) -> Tags {
        Tags {
            out: String::with_capacity(64 * 1024),
            next_handle: first_handle,
        }
    }

    /// A new handle.
    pub(super) fn handle(&mut self) -> u32 {
        let h = self.next_handle;
        self.next_handle += 1;
        h
    }

    /// `code` then `value`.
    pub(super) fn tag(&mut self, code: u16, value: &str) -> &mut Tags {
        let _ = writeln!(self.out, "{code:>3}\n{value}");
        self
    }

    /// `code` then an integer.
    pub(super) fn int(&mut self, code: u16, value: i64) -> &mut Tags {
        let _ = writeln!(self.out, "{code:>3}\n{value}");
        self
    }

    /// `code` then a handle in hexadecimal.
    pub(super) fn hex(&mut self, code: u16, handle: u32) -> &mut Tags {
        let _ = writeln!(self.out, "{code:>3}\n{handle:X}");
        self
    }

    /// `code` then a real in the shortest form that reads back to the same `f64`.
    pub(super) fn real(&mut self, code: u16, value: f64) -> &mut Tags {
        let _ = writeln!(self.out, "{code:>3}");
        let mut digits = Vec::with_capacity(24);
        push_number(&mut digits, value);
        self.out
            .push_str(std::str::from_utf8(&digits).unwrap_or("0"));
        self.out.push('\n');
        self
    }

    /// A point: `code`, `code + 10`, `code + 20` for x, y, z.
    pub(super) fn point(&mut self, code: u16, p: [f64; 3]) -> &mut Tags {
        self.real(code, p[0])
            .real(code + 10, p[1])
            .real(code + 20, p[2])
    }

    /// The start of an entity or object: `0 TYPE`, its handle and its owner.
    pub(super) fn start(&mut self, kind: &str, owner: u32) -> u32 {
        let handle = self.handle();
        self.tag(0, kind).hex(5, handle).hex(330, owner);
        handle
    }

    /// Extended data of the application `NEUTROSPLINE`.
    pub(super) fn xdata(&mut self, values: &[XValue]) {
        self.tag(1001, APP);
        for value in values {
            match value {
                XValue::Text(s) => self.tag(1000, s),
                XValue::Short(n) => self.int(1070, i64::from(*n)),
                XValue::Long(n) => self.int(1071, i64::from(*n)),
                XValue::Real(r) => self.real(1040, *r),
            };
        }
    }
}

/// A symbol table: `0 TABLE`, its name, handle and entry count; then `entries` writes the
/// entries, given the table's handle.
fn table(t: &mut Tags, name: &str, count: i64, entries: impl FnOnce(&mut Tags, u32)) {
    let handle = t.handle();
    t.tag(0, "TABLE").tag(2, name).hex(5, handle).hex(330, 0);
    t.tag(100, "AcDbSymbolTable").int(70, count);
    if name == "DIMSTYLE" {
        t.tag(100, "AcDbDimStyleTable");
    }
    entries(t, handle);
    t.tag(0, "ENDTAB");
}

/// A table entry: type, handle, owner, the two subclass markers, name and flags 0.
fn entry(t: &mut Tags, kind: &str, owner: u32, class: &str, name: &str) {
    let handle = t.handle();
    let handle_code = if kind == "DIMSTYLE" { 105 } else { 5 };
    t.tag(0, kind).hex(handle_code, handle).hex(330, owner);
    t.tag(100, "AcDbSymbolTableRecord").tag(100, class);
    t.tag(2, name).int(70, 0);
}

/// The handles the BLOCKS section refers to.
struct BlockRecords {
    model: u32,
    paper: u32,
}

fn tables(t: &mut Tags, view: ([f64; 2], f64)) -> BlockRecords {
    t.tag(0, "SECTION").tag(2, "TABLES");
    table(t, "VPORT", 1, |t, h| {
        entry(t, "VPORT", h, "AcDbViewportTableRecord", "*ACTIVE");
        let ([cx, cy], height) = view;
        t.real(10, 0.0).real(20, 0.0).real(11, 1.0).real(21, 1.0);
        t.real(12, cx).real(22, cy);
        t.real(13, 0.0).real(23, 0.0).real(14, 1.0).real(24, 1.0);
        t.real(15, 0.0)
            .real(25, 0.0)
            .real(16, 0.0)
            .real(26, 0.0)
            .real(36, 1.0);
        t.real(17, 0.0).real(27, 0.0).real(37, 0.0);
        t.real(40, height).real(41, 1.5).real(42, 50.0);
        t.real(43, 0.0).real(44, 0.0).real(50, 0.0).real(51, 0.0);
        t.int(71, 0).int(72, 100).int(73, 1).int(74, 3);
        t.int(75, 0).int(76, 0).int(77, 0).int(78, 0);
    });
    table(t, "LTYPE", 3, |t, h| {
        for name in ["ByBlock", "ByLayer", "Continuous"] {
            entry(t, "LTYPE", h, "AcDbLinetypeTableRecord", name);
            let text = if name == "Continuous" {
                "Solid line"
            } else {
                ""
            };
            t.tag(3, text).int(72, 65).int(73, 0).real(40, 0.0);
        }
    });
    table(t, "LAYER", 1, |t, h| {
        entry(t, "LAYER", h, "AcDbLayerTableRecord", "0");
        t.int(62, 7).tag(6, "Continuous").int(370, -3);
    });
    table(t, "STYLE", 1, |t, h| {
        entry(t, "STYLE", h, "AcDbTextStyleTableRecord", "Standard");
        t.real(40, 0.0).real(41, 1.0).real(50, 0.0).int(71, 0);
        t.real(42, 2.5).tag(3, "txt").tag(4, "");
    });
    table(t, "VIEW", 0, |_, _| {});
    table(t, "UCS", 0, |_, _| {});
    table(t, "APPID", 2, |t, h| {
        for name in ["ACAD", APP] {
            entry(t, "APPID", h, "AcDbRegAppTableRecord", name);
        }
    });
    table(t, "DIMSTYLE", 1, |t, h| {
        entry(t, "DIMSTYLE", h, "AcDbDimStyleTableRecord", "Standard");
    });
    let mut records = BlockRecords { model: 0, paper: 0 };
    table(t, "BLOCK_RECORD", 2, |t, h| {
        records = BlockRecords {
            model: t.handle(),
            paper: t.handle(),
        };
        for (handle, name) in [
            (records.model, "*Model_Space"),
            (records.paper, "*Paper_Space"),
        ] {
            t.tag(0, "BLOCK_RECORD").hex(5, handle).hex(330, h);
            t.tag(100, "AcDbSymbolTableRecord")
                .tag(100, "AcDbBlockTableRecord");
            t.tag(2, name);
        }
    });
    t.tag(0, "ENDSEC");
    records
}

fn blocks(t: &mut Tags, records: &BlockRecords) {
    t.tag(0, "SECTION").tag(2, "BLOCKS");
    for (owner, name, paper) in [
        (records.model, "*Model_Space", false),
        (records.paper, "*Paper_Space", true),
    ] {
        t.start("BLOCK", owner);
        t.tag(100, "AcDbEntity");
        if paper {
            t.int(67, 1);
        }
        t.tag(8, "0")
            .tag(100, "AcDbBlockBegin")
            .tag(2, name)
            .int(70, 0);
        t.point(10, [0.0; 3]).tag(3, name).tag(1, "");
        t.start("ENDBLK", owner);
        t.tag(100, "AcDbEntity");
        if paper {
            t.int(67, 1);
        }
        t.tag(8, "0").tag(100, "AcDbBlockEnd");
    }
    t.tag(0, "ENDSEC");
}

fn objects(t: &mut Tags) {
    t.tag(0, "SECTION").tag(2, "OBJECTS");
    let root = t.handle();
    let group = t.handle();
    t.tag(0, "DICTIONARY").hex(5, root).hex(330, 0);
    t.tag(100, "AcDbDictionary").int(281, 1);
    t.tag(3, "ACAD_GROUP").hex(350, group);
    t.tag(0, "DICTIONARY").hex(5, group).hex(330, root);
    t.tag(100, "AcDbDictionary").int(281, 1);
    t.tag(0, "ENDSEC");
}

/// The extent of the drawing: `$EXTMIN` and `$EXTMAX`.
pub(super) type Extent = ([f64; 3], [f64; 3]);

/// A whole DXF R2004 document whose ENTITIES section `entities` writes, given the handle of
/// the model space's block record (every entity's owner). `extent` sets `$EXTMIN`, `$EXTMAX`
/// and the initial view, so that a viewer shows the whole drawing.
pub(super) fn document(extent: Extent, entities: impl FnOnce(&mut Tags, u32)) -> String {
    let (lo, hi) = extent;
    let center = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let height = ((hi[1] - lo[1]).max((hi[0] - lo[0]) / 1.5) * 1.1).max(1e-9);
    // Handles 1.. are the tables, blocks, entities and objects; the header's `$HANDSEED` is
    // written last, in front of them.
    let mut body = Tags::new(1);
    body.tag(0, "SECTION").tag(2, "CLASSES").tag(0, "ENDSEC");
    let records = tables(&mut body, (center, height));
    blocks(&mut body, &records);
    body.tag(0, "SECTION").tag(2, "ENTITIES");
    entities(&mut body, records.model);
    body.tag(0, "ENDSEC");
    objects(&mut body);
    body.tag(0, "EOF");

    let mut head = Tags::new(0);
    head.tag(0, "SECTION").tag(2, "HEADER");
    head.tag(9, "$ACADVER").tag(1, "AC1018");
    head.tag(9, "$DWGCODEPAGE").tag(3, "ANSI_1252");
    head.tag(9, "$INSBASE").point(10, [0.0; 3]);
    head.tag(9, "$EXTMIN").point(10, lo);
    head.tag(9, "$EXTMAX").point(10, hi);
    head.tag(9, "$INSUNITS").int(70, 0);
    head.tag(9, "$HANDSEED").hex(5, body.next_handle);
    head.tag(0, "ENDSEC");
    head.out.push_str(&body.out);
    head.out
}
