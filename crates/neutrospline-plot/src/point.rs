//! The point every figure is drawn from: a position and its three degrees.
//!
//! A leaf module (it imports nothing from the crate): the model samples into it, and what is
//! drawn (`quantity`), the axes and the views read it.

/// A point as the renderer uses it: position padded to 3-D (z = 0 for planar models) and
/// the degrees `[truth, indeterminacy, falsity]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pt {
    pub pos: [f64; 3],
    pub deg: [f64; 3],
}
