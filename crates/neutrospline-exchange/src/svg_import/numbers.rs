//! Numbers of SVG's grammar (SVG 1.1, section 8.3.9), shared by path data, point lists and
//! transforms.

/// Numbers of SVG's grammar, in path data, point lists and transforms.
pub(super) struct Numbers<'a> {
    /// The text read.
    pub(super) text: &'a [u8],
    /// The offset of the next byte.
    pub(super) k: usize,
}

impl<'a> Numbers<'a> {
    pub(super) fn new(text: &'a str) -> Numbers<'a> {
        Numbers {
            text: text.as_bytes(),
            k: 0,
        }
    }

    /// Skips white space and at most one comma.
    pub(super) fn separator(&mut self) {
        while self.k < self.text.len() && self.text[self.k].is_ascii_whitespace() {
            self.k += 1;
        }
        if self.k < self.text.len() && self.text[self.k] == b',' {
            self.k += 1;
            while self.k < self.text.len() && self.text[self.k].is_ascii_whitespace() {
                self.k += 1;
            }
        }
    }

    pub(super) fn at_end(&mut self) -> bool {
        self.separator();
        self.k >= self.text.len()
    }

    /// The character position (1-based) of the next token, for messages.
    pub(super) fn position(&self) -> usize {
        self.k + 1
    }

    /// The next number: sign, digits, fraction, exponent.
    pub(super) fn number(&mut self) -> Result<f64, String> {
        self.separator();
        let start = self.k;
        let t = self.text;
        let mut k = self.k;
        if k < t.len() && matches!(t[k], b'+' | b'-') {
            k += 1;
        }
        let digits = |k: &mut usize| {
            let s = *k;
            while *k < t.len() && t[*k].is_ascii_digit() {
                *k += 1;
            }
            *k > s
        };
        let whole = digits(&mut k);
        let mut fraction = false;
        if k < t.len() && t[k] == b'.' {
            k += 1;
            fraction = digits(&mut k);
        }
        if !whole && !fraction {
            let found = String::from_utf8_lossy(&t[start..(start + 1).min(t.len())]).into_owned();
            return Err(if found.is_empty() {
                format!(
                    "a number is missing at character {} (the data ends)",
                    start + 1
                )
            } else {
                format!(
                    "expected a number at character {}, found `{found}`",
                    start + 1
                )
            });
        }
        if k < t.len() && matches!(t[k], b'e' | b'E') {
            let mut e = k + 1;
            if e < t.len() && matches!(t[e], b'+' | b'-') {
                e += 1;
            }
            if digits(&mut e) {
                k = e;
            }
        }
        self.k = k;
        let text = std::str::from_utf8(&t[start..k]).unwrap_or("");
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(format!(
                "`{text}` at character {} is not a finite number",
                start + 1
            )),
        }
    }

    /// An arc flag: `0` or `1` (no separator needed after it).
    pub(super) fn flag(&mut self) -> Result<bool, String> {
        self.separator();
        match self.text.get(self.k) {
            Some(b'0') => {
                self.k += 1;
                Ok(false)
            }
            Some(b'1') => {
                self.k += 1;
                Ok(true)
            }
            _ => Err(format!(
                "an arc flag at character {} is not 0 or 1",
                self.k + 1
            )),
        }
    }

    pub(super) fn pair(&mut self) -> Result<[f64; 2], String> {
        Ok([self.number()?, self.number()?])
    }
}
