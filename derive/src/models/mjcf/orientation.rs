//! MJCF's orientations (`quat`, `axisangle`, `euler` with `eulerseq`, `xyaxes`, `zaxis`) and
//! angles in the compiler's unit: exact where the rotation is (degrees are exact multiples of
//! `pi`; quaternions give rational matrices).

use planar_arm_core::mechanics::spatial::FixedAngle;
use planar_arm_core::ring::{int, ratio, to_f64, Rational};

use super::Attrs;
use crate::models::frame::{decimal, Rotation};
use crate::models::tree::FileError;

/// `<compiler>`'s settings that change the numbers read.
pub struct Compiler {
    pub degrees: bool,
    /// Three of `xyzXYZ`: lower case about the moving axes, upper case about the fixed ones.
    pub eulerseq: String,
}

impl Compiler {
    /// An angle written in the compiler's unit.
    pub fn angle(&self, v: &Rational) -> FixedAngle {
        if self.degrees {
            FixedAngle::pi(v / int(180))
        } else {
            FixedAngle {
                radians: v.clone(),
                pi_multiple: int(0),
            }
        }
    }

    /// An angle in radians as a number (a hinge's range): exact when written in radians.
    pub fn radians(&self, v: &Rational) -> Rational {
        if self.degrees {
            decimal(to_f64(v).unwrap_or(0.0).to_radians())
        } else {
            v.clone()
        }
    }
}

fn f(r: &Rational) -> f64 {
    to_f64(r).unwrap_or(0.0)
}

/// A float rotation whose entries are all exactly 0 or +-1 is a signed permutation: exact.
fn snap(m: [[f64; 3]; 3]) -> Rotation {
    if m.iter().flatten().all(|x| *x == 0.0 || x.abs() == 1.0) {
        Rotation::Exact(m.map(|row| row.map(|x| ratio(x as i64, 1))))
    } else {
        Rotation::Float(m)
    }
}

/// The rotation taking `+z` to the direction of `v` by the shortest turn, as MuJoCo's `zaxis`.
pub fn z_to(v: [f64; 3]) -> Rotation {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let u = v.map(|x| x / n);
    let axis = [-u[1], u[0], 0.0];
    let s = axis[0].hypot(axis[1]);
    if s < 1e-14 {
        return if u[2] > 0.0 {
            Rotation::identity()
        } else {
            // Half a turn about x, as MuJoCo does for -z.
            snap([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]])
        };
    }
    let angle = s.atan2(u[2]);
    match Rotation::axis_angle(
        &axis.map(|x| x / s),
        &FixedAngle {
            radians: decimal(angle),
            pi_multiple: int(0),
        },
    ) {
        Rotation::Float(m) => snap(m.map(|r| r.map(|x| if x.abs() < 1e-15 { 0.0 } else { x }))),
        exact => exact,
    }
}

/// The orientation `node` states (identity if none); an error when it states two.
pub fn orientation(xml: &Attrs<'_, '_>, c: &Compiler) -> Result<Rotation, FileError> {
    let given: Vec<&str> = ["quat", "axisangle", "euler", "xyaxes", "zaxis"]
        .into_iter()
        .filter(|k| xml.node.attribute(*k).is_some())
        .collect();
    if given.len() > 1 {
        return Err(xml.error(format!(
            "<{}> gives its orientation twice ({})",
            xml.node.tag_name().name(),
            given.join(", ")
        )));
    }
    if let Some(q) = xml.numbers("quat", 4)? {
        return Ok(Rotation::quaternion(&[
            q[0].clone(),
            q[1].clone(),
            q[2].clone(),
            q[3].clone(),
        ]));
    }
    if let Some(a) = xml.numbers("axisangle", 4)? {
        let axis = [f(&a[0]), f(&a[1]), f(&a[2])];
        if axis == [0.0; 3] {
            return Err(xml.error("`axisangle` with a zero axis"));
        }
        return Ok(Rotation::axis_angle(&axis, &c.angle(&a[3])));
    }
    if let Some(e) = xml.triple("euler")? {
        let seq: Vec<char> = c.eulerseq.chars().collect();
        let mut r = Rotation::identity();
        for (k, ch) in seq.iter().enumerate() {
            let axis = match ch.to_ascii_lowercase() {
                'x' => [1.0, 0.0, 0.0],
                'y' => [0.0, 1.0, 0.0],
                _ => [0.0, 0.0, 1.0],
            };
            let turn = Rotation::axis_angle(&axis, &c.angle(&e[k]));
            // Moving axes multiply on the right, fixed ones on the left.
            r = if ch.is_ascii_lowercase() {
                r.mul(&turn)
            } else {
                turn.mul(&r)
            };
        }
        return Ok(r);
    }
    if let Some(v) = xml.numbers("xyaxes", 6)? {
        let v: Vec<f64> = v.iter().map(f).collect();
        let norm = |a: [f64; 3]| {
            let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
            a.map(|x| x / n)
        };
        let x = norm([v[0], v[1], v[2]]);
        let d = x[0] * v[3] + x[1] * v[4] + x[2] * v[5];
        let y = norm([v[3] - d * x[0], v[4] - d * x[1], v[5] - d * x[2]]);
        let z = [
            x[1] * y[2] - x[2] * y[1],
            x[2] * y[0] - x[0] * y[2],
            x[0] * y[1] - x[1] * y[0],
        ];
        if z.iter().any(|c| !c.is_finite()) {
            return Err(xml.error("`xyaxes` with parallel or zero axes"));
        }
        return Ok(snap(core::array::from_fn(|i| [x[i], y[i], z[i]])));
    }
    if let Some(v) = xml.triple("zaxis")? {
        let v = v.each_ref().map(f);
        if v == [0.0; 3] {
            return Err(xml.error("`zaxis` of zero length"));
        }
        return Ok(z_to(v));
    }
    Ok(Rotation::identity())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degrees_are_exact_quarter_turns() {
        let c = Compiler {
            degrees: true,
            eulerseq: "xyz".into(),
        };
        let texts = vec![("m.xml".to_string(), "<body euler=\"90 0 0\"/>".to_string())];
        let files = super::super::files::Files::parse(&texts).unwrap();
        let defaults = super::super::defaults::Defaults::read(&files, &[]);
        let node = files.main().doc.root_element();
        let r = orientation(&Attrs::new(&files, &defaults, node, "main"), &c).unwrap();
        let Rotation::Exact(m) = r else {
            panic!("not exact")
        };
        // Rx(90 degrees) takes y to z.
        assert_eq!(m[2][1], int(1));
    }

    #[test]
    fn zaxis_turns_z_onto_the_axis() {
        for v in [[1.0, 0.0, 0.0], [0.3, -0.4, 0.5], [0.0, 0.0, -2.0]] {
            let m = z_to(v).float();
            let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            for i in 0..3 {
                assert!((m[i][2] - v[i] / n).abs() < 1e-15, "{v:?}: {m:?}");
            }
        }
    }
}
