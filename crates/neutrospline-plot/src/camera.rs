//! An orthographic 3-D camera given by azimuth and elevation.

/// Orthographic camera looking at the origin.
///
/// The viewer sits in the direction
/// `(cos(el) cos(az), cos(el) sin(az), sin(el))` from the scene (azimuth `az` measured in the
/// x-y plane from the x axis, elevation `el` above that plane, both in degrees). The z axis is
/// drawn vertical on screen for any elevation strictly between -90 and 90.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Camera {
    /// Screen-right direction in scene coordinates.
    right: [f64; 3],
    /// Screen-up direction in scene coordinates.
    up: [f64; 3],
    /// Direction from the scene towards the viewer.
    toward: [f64; 3],
}

/// A projected point: screen x (right), screen y (up) and depth (larger is nearer the viewer).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Projected {
    pub x: f64,
    pub y: f64,
    pub depth: f64,
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl Camera {
    pub(crate) fn new(azimuth_deg: f64, elevation_deg: f64) -> Camera {
        let (sa, ca) = azimuth_deg.to_radians().sin_cos();
        let (se, ce) = elevation_deg.to_radians().sin_cos();
        Camera {
            right: [-sa, ca, 0.0],
            up: [-se * ca, -se * sa, ce],
            toward: [ce * ca, ce * sa, se],
        }
    }

    pub(crate) fn project(&self, p: [f64; 3]) -> Projected {
        Projected {
            x: dot(p, self.right),
            y: dot(p, self.up),
            depth: dot(p, self.toward),
        }
    }

    /// Screen direction (x right, y up) of a scene direction `v`.
    pub(crate) fn project_dir(&self, v: [f64; 3]) -> (f64, f64) {
        (dot(v, self.right), dot(v, self.up))
    }

    /// Direction from the scene towards the viewer.
    pub(crate) fn toward(&self) -> [f64; 3] {
        self.toward
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn camera_basis_is_orthonormal() {
        for (az, el) in [(-55.0, 25.0), (0.0, 0.0), (123.0, -40.0), (10.0, 90.0)] {
            let c = Camera::new(az, el);
            for (a, b, want) in [
                (c.right, c.right, 1.0),
                (c.up, c.up, 1.0),
                (c.toward, c.toward, 1.0),
                (c.right, c.up, 0.0),
                (c.right, c.toward, 0.0),
                (c.up, c.toward, 0.0),
            ] {
                assert!((dot(a, b) - want).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn camera_z_axis_is_vertical() {
        let c = Camera::new(-55.0, 25.0);
        let (x, y) = c.project_dir([0.0, 0.0, 1.0]);
        assert!(x.abs() < 1e-12 && y > 0.0);
    }

    #[test]
    fn camera_front_view() {
        // Azimuth -90: the viewer looks along +y, x runs to the right.
        let c = Camera::new(-90.0, 0.0);
        let p = c.project([1.0, 0.0, 0.0]);
        assert!((p.x - 1.0).abs() < 1e-12 && p.y.abs() < 1e-12);
        assert!(c.project([0.0, -1.0, 0.0]).depth > 0.0);
    }
}
