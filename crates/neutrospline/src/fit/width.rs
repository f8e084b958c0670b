//! Loop sizes known at compile time where it pays: the per-point loops of fitting.

/// A count that sizes the per-point loops: a constant where the loops are worth unrolling,
/// or a runtime value. One body serves both.
pub(super) trait Width: Copy {
    fn get(self) -> usize;
}

#[derive(Clone, Copy)]
pub(super) struct Fixed<const C: usize>;

impl<const C: usize> Width for Fixed<C> {
    #[inline(always)]
    fn get(self) -> usize {
        C
    }
}

#[derive(Clone, Copy)]
pub(super) struct Dynamic(pub(super) usize);

impl Width for Dynamic {
    #[inline(always)]
    fn get(self) -> usize {
        self.0
    }
}

/// Evaluates `$body` with `$name` bound to the [`Width`] of `$w` basis values
/// per row (constant for cubics, the default degree) or of `$c` channels per point (constant
/// for 2 or 3 positions, and 5 or 6 with the degrees).
macro_rules! with_width {
    (row $name:ident = $w:expr => $body:expr) => {
        match $w {
            4 => {
                let $name = $crate::fit::width::Fixed::<4>;
                $body
            }
            w => {
                let $name = $crate::fit::width::Dynamic(w);
                $body
            }
        }
    };
    (channels $name:ident = $c:expr => $body:expr) => {
        match $c {
            2 => {
                let $name = $crate::fit::width::Fixed::<2>;
                $body
            }
            3 => {
                let $name = $crate::fit::width::Fixed::<3>;
                $body
            }
            5 => {
                let $name = $crate::fit::width::Fixed::<5>;
                $body
            }
            6 => {
                let $name = $crate::fit::width::Fixed::<6>;
                $body
            }
            c => {
                let $name = $crate::fit::width::Dynamic(c);
                $body
            }
        }
    };
}
pub(super) use with_width;
