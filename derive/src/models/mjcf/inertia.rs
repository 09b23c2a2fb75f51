//! A body's mass properties as MuJoCo's compiler finds them: its `<inertial>`, or the sum of its
//! geoms' (sphere, capsule, cylinder, box, ellipsoid), each a solid of its `mass` or of its
//! `density` (default 1000) times its volume.
//!
//! With `mass` given the moments are exact (rational in the sizes); a volume brings in `pi`, so
//! a mass from `density` is the `f64` MuJoCo computes, written as its shortest decimal.

use planar_arm_core::ring::{int, ratio, to_f64, Rational};

use super::orientation::{orientation, z_to, Compiler};
use super::Attrs;
use crate::models::frame::{decimal, Inertial, Rotation, Vec3};
use crate::models::tree::FileError;

/// A solid's principal moments as a function of its mass.
type Moments = Box<dyn Fn(&Rational) -> [Rational; 3]>;

fn f(r: &Rational) -> f64 {
    to_f64(r).unwrap_or(0.0)
}

/// `<inertial pos quat mass diaginertia|fullinertia>`, in the body's frame.
pub fn inertial(a: &Attrs<'_, '_>, c: &Compiler) -> Result<Inertial, FileError> {
    let mass = a.number("mass")?.unwrap_or_else(|| int(0));
    let oriented = ["quat", "axisangle", "euler", "xyaxes", "zaxis"]
        .iter()
        .any(|k| a.node.attribute(*k).is_some());
    if oriented && a.node.attribute("fullinertia").is_some() {
        // As MuJoCo's schema: a full tensor is in the body's axes.
        return Err(a.error("an <inertial> with `fullinertia` takes no orientation"));
    }
    let inertia: [Rational; 6] = if let Some(full) = a.numbers("fullinertia", 6)? {
        // MuJoCo's order: ixx iyy izz ixy ixz iyz, as ours.
        core::array::from_fn(|i| full[i].clone())
    } else if let Some(d) = a.triple("diaginertia")? {
        [
            d[0].clone(),
            d[1].clone(),
            d[2].clone(),
            int(0),
            int(0),
            int(0),
        ]
    } else {
        return Err(a.error("an <inertial> needs `diaginertia` or `fullinertia`"));
    };
    let body = Inertial {
        mass,
        com: Default::default(),
        inertia,
    };
    if body.is_negative() {
        return Err(a.error("a negative mass or moment of inertia"));
    }
    let pos = a.triple("pos")?.unwrap_or_default();
    Ok(body.placed(&pos, &orientation(a, c)?))
}

/// Whether the principal moments of the tensor (xx, yy, zz, xy, xz, yz) break `A + B >= C`:
/// the second moment `tr/2 E - I` is not positive semi-definite (a principal minor is
/// negative), decided exactly.
pub fn breaks_triangle(i: &[Rational; 6]) -> bool {
    let half = (&i[0] + &i[1] + &i[2]) / int(2);
    let [xx, yy, zz, xy, xz, yz] = i.clone();
    let (a, b, c) = (&half - &xx, &half - &yy, &half - &zz);
    let (d, e, f) = (-xy, -xz, -yz);
    let minors = [
        a.clone(),
        b.clone(),
        c.clone(),
        &a * &b - &d * &d,
        &a * &c - &e * &e,
        &b * &c - &f * &f,
        &a * (&b * &c - &f * &f) - &d * (&d * &c - &f * &e) + &e * (&d * &f - &b * &e),
    ];
    minors.iter().any(num_traits::Signed::is_negative)
}

/// A geom's solid, in the body's frame; `None` for a geom of no mass.
pub fn geom(a: &Attrs<'_, '_>, c: &Compiler) -> Result<Option<Inertial>, FileError> {
    let kind = a.get("type").unwrap_or("sphere");
    let explicit = a.number("mass")?;
    if explicit.as_ref().is_some_and(num_traits::Zero::is_zero) {
        return Ok(None);
    }
    let density = a.number("density")?.unwrap_or_else(|| int(1000));
    if explicit.is_none() && num_traits::Zero::is_zero(&density) {
        return Ok(None);
    }
    let size = a.numbers("size", 0)?.unwrap_or_default();
    let s = |i: usize| size.get(i).cloned().unwrap_or_else(|| int(0));
    let fromto = a.numbers("fromto", 6)?;
    // The solid's half-sizes along its axes and its placement.
    let (mut half, pos, rot): ([Rational; 3], Vec3, Rotation) = match &fromto {
        Some(ft) => {
            let d: [Rational; 3] = core::array::from_fn(|i| &ft[i + 3] - &ft[i]);
            let len = d.iter().map(|x| f(x) * f(x)).sum::<f64>().sqrt();
            if len == 0.0 {
                return Err(a.error("`fromto` with equal ends"));
            }
            let exact_len = axis_length(&d);
            let h = exact_len.map_or_else(|| decimal(len / 2.0), |l| l / int(2));
            let mid = core::array::from_fn(|i| (&ft[i] + &ft[i + 3]) / int(2));
            ([s(0), s(1), h], mid, z_to(d.each_ref().map(f)))
        }
        None => (
            [s(0), s(1), s(2)],
            a.triple("pos")?.unwrap_or_default(),
            orientation(a, c)?,
        ),
    };
    let pi = core::f64::consts::PI;
    let (volume, moments): (f64, Moments) = match kind {
        "sphere" => {
            let r = half[0].clone();
            let r2 = &r * &r;
            (
                4.0 * pi * f(&r) * f(&r) * f(&r) / 3.0,
                Box::new(move |m| {
                    let i = m * &r2 * ratio(2, 5);
                    [i.clone(), i.clone(), i]
                }),
            )
        }
        "capsule" | "cylinder" => {
            if fromto.is_none() {
                half[2] = half[1].clone();
            }
            let (r, h) = (half[0].clone(), &half[2] * int(2));
            let cylinder = kind == "cylinder";
            let (rf, hf) = (f(&r), f(&h));
            let v = if cylinder {
                pi * rf * rf * hf
            } else {
                pi * (rf * rf * hf + 4.0 * rf * rf * rf / 3.0)
            };
            (
                v,
                Box::new(move |m| {
                    let r2 = &r * &r;
                    // The hemispheres' share of the mass, by volume: 4r / (4r + 3h).
                    let ms = if cylinder {
                        int(0)
                    } else {
                        m * &r * int(4) / (&r * int(4) + &h * int(3))
                    };
                    let mc = m - &ms;
                    let side = &mc * (&r2 * int(3) + &h * &h) / int(12)
                        + &ms * &r2 * ratio(2, 5)
                        + &ms * &h * (&r * int(3) + &h * int(2)) / int(8);
                    let axial = &mc * &r2 / int(2) + &ms * &r2 * ratio(2, 5);
                    [side.clone(), side, axial]
                }),
            )
        }
        "box" | "ellipsoid" => {
            let boxed = kind == "box";
            let h = half.clone();
            // In MuJoCo's order of operations, so that a mass from density is its float.
            let abc = f(&h[0]) * f(&h[1]) * f(&h[2]);
            let v = if boxed {
                abc * 8.0
            } else {
                4.0 * pi * abc / 3.0
            };
            (
                v,
                Box::new(move |m| {
                    let k = if boxed { ratio(1, 3) } else { ratio(1, 5) };
                    let sq = |i: usize| &h[i] * &h[i];
                    [
                        m * (sq(1) + sq(2)) * &k,
                        m * (sq(0) + sq(2)) * &k,
                        m * (sq(0) + sq(1)) * &k,
                    ]
                }),
            )
        }
        other => {
            return Err(a.error(format!(
                "a `{other}` geom's mass properties need its shape; give the body an \
                 <inertial>, or the geom `mass=\"0\"`"
            )))
        }
    };
    let mass = explicit.unwrap_or_else(|| decimal(f(&density) * volume));
    let [xx, yy, zz] = moments(&mass);
    let solid = Inertial {
        mass,
        com: Default::default(),
        inertia: [xx, yy, zz, int(0), int(0), int(0)],
    };
    Ok(Some(solid.placed(&pos, &rot)))
}

/// `|d|` when it is rational (one non-zero component, or a Pythagorean triple).
fn axis_length(d: &[Rational; 3]) -> Option<Rational> {
    let nonzero: Vec<&Rational> = d
        .iter()
        .filter(|x| !num_traits::Zero::is_zero(*x))
        .collect();
    match nonzero.as_slice() {
        [one] => Some(num_traits::Signed::abs(*one)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn body(xml: &str) -> Inertial {
        let texts = vec![("m.xml".to_string(), xml.to_string())];
        let files = super::super::files::Files::parse(&texts).unwrap();
        let defaults = super::super::defaults::Defaults::read(&files, &[]);
        let node = files.main().doc.root_element();
        let c = Compiler {
            degrees: true,
            eulerseq: "xyz".into(),
        };
        geom(&Attrs::new(&files, &defaults, node, "main"), &c)
            .unwrap()
            .unwrap()
    }

    #[test]
    fn a_rod_along_z_has_the_textbook_moments() {
        // A cylinder of mass 1, radius 0 in the limit: m h^2 / 12 across, here with r = 0.1.
        let g = body("<geom type=\"cylinder\" fromto=\"0 0 0 0 0 1\" size=\"0.1\" mass=\"1\"/>");
        assert_eq!(g.com, [int(0), int(0), ratio(1, 2)]);
        // (3 r^2 + h^2) / 12 = (0.03 + 1) / 12.
        assert_eq!(g.inertia[0], ratio(103, 1200));
        assert_eq!(g.inertia[2], ratio(1, 200));
    }

    #[test]
    fn a_capsule_splits_its_mass_by_volume() {
        // A capsule of zero length is a sphere: 2/5 m r^2 every way.
        let g = body("<geom type=\"capsule\" size=\"0.5 0\" mass=\"2\"/>");
        assert_eq!(g.inertia[..3], [ratio(1, 5), ratio(1, 5), ratio(1, 5)]);
    }

    #[test]
    fn the_triangle_inequality_is_decided_exactly() {
        let t = |v: [i64; 6]| v.map(int);
        assert!(!breaks_triangle(&t([1, 1, 2, 0, 0, 0])));
        assert!(breaks_triangle(&t([1, 1, 3, 0, 0, 0])));
        // Corke's PUMA waist: only Iyy.
        assert!(breaks_triangle(&t([0, 7, 0, 0, 0, 0])));
        // A valid tensor turned off its axes stays valid: diag(2, 3, 4) about z by 45 degrees.
        let turned = [
            ratio(5, 2),
            ratio(5, 2),
            int(4),
            ratio(1, 2),
            int(0),
            int(0),
        ];
        assert!(!breaks_triangle(&turned));
    }

    #[test]
    fn density_gives_the_float_mass() {
        let g = body("<geom type=\"box\" size=\"0.1 0.2 0.3\"/>");
        assert_eq!(g.mass, decimal(1000.0 * (0.1 * 0.2 * 0.3 * 8.0)));
    }
}
