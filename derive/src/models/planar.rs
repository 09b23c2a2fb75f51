//! A model file's chain as a planar arm: every hinge about one axis `n` or its opposite (the
//! plane's normal; a hinge about `-n` is `reversed`), every slide in the plane.
//!
//! The plane's frame: its origin at the first joint, `x` along it if it slides, else from it
//! toward the next joint (or along a slide, or toward the tip), `y = n x x`. Each link's own `x` at `q = 0`
//! points toward the next joint (or the tool; a slide's along the slide), and its joint's
//! `offset` is the turn from the previous link's `x` (a quarter turn exactly when the file's
//! axes are aligned). Offsets along `n` do not change a planar motion and are dropped; so is
//! gravity's part along `n`, which does no work. A slide whose next joint lies off its line,
//! which a planar link cannot say, is an error naming the joint.

use num_traits::{Signed, Zero};
use planar_arm_core::ring::{int, to_f64, Rational};
use planar_arm_core::spatial::FixedAngle;
use planar_arm_core::Poly;
use planar_arm_core::{JointKind, LinkSpec, Offset};

use super::chain::Chain;
use super::frame::{decimal, Pose, Vec3};
use super::tree::FileError;

fn f(r: &Rational) -> f64 {
    to_f64(r).unwrap_or(0.0)
}

fn dot(a: &Vec3, b: &Vec3) -> Rational {
    (0..3).map(|i| &a[i] * &b[i]).sum()
}

fn cross(a: &Vec3, b: &Vec3) -> Vec3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn sub(a: &Vec3, b: &Vec3) -> Vec3 {
    core::array::from_fn(|i| &a[i] - &b[i])
}

fn norm(a: &Vec3) -> f64 {
    a.iter().map(|x| f(x) * f(x)).sum::<f64>().sqrt()
}

/// `v` of unit length: exact along a coordinate axis, else each entry the shortest decimal.
fn unit(v: &Vec3) -> Vec3 {
    let nonzero: Vec<usize> = (0..3).filter(|&i| !v[i].is_zero()).collect();
    if let [i] = nonzero.as_slice() {
        let mut u: Vec3 = Default::default();
        u[*i] = if v[*i].is_negative() { int(-1) } else { int(1) };
        return u;
    }
    let n = norm(v);
    v.clone().map(|x| decimal(f(&x) / n))
}

/// Whether `v` is zero, to rounding against `scale`.
fn negligible(v: &Vec3, scale: f64) -> bool {
    v.iter().all(Zero::is_zero) || norm(v) <= 1e-12 * scale.max(1e-300)
}

fn small(x: &Rational, scale: f64) -> bool {
    x.is_zero() || f(x).abs() <= 1e-12 * scale.max(1e-300)
}

/// What a planar derive takes from a file.
pub struct Planar {
    pub links: Vec<LinkSpec<Poly>>,
    /// Gravity's acceleration `(gx, gy)` in the plane's frame.
    pub gravity: (Poly, Poly),
    /// Notes for the docs: the plane chosen, what was dropped.
    pub notes: Vec<String>,
}

/// The angle from `a` to `b` (unit vectors of the plane with normal `n`), counter-clockwise
/// about `n`; `None` when it is zero. A multiple of `pi/2` to rounding is that multiple
/// exactly, so that axis-aligned models stay exact.
fn offset_between(a: &Vec3, b: &Vec3, n: &Vec3) -> Option<FixedAngle> {
    let (c, s) = (f(&dot(a, b)), f(&dot(&cross(a, b), n)));
    let angle = s.atan2(c);
    let quarters = (angle / core::f64::consts::FRAC_PI_2).round();
    if (angle - quarters * core::f64::consts::FRAC_PI_2).abs() <= 1e-12 {
        let k = quarters as i64;
        return (k != 0).then(|| FixedAngle::pi(Rational::new(k.into(), 2.into())));
    }
    Some(FixedAngle {
        radians: decimal(angle),
        pi_multiple: int(0),
    })
}

fn show(v: &Vec3) -> String {
    let parts: Vec<String> = v.iter().map(|x| format!("{}", f(x))).collect();
    format!("({})", parts.join(", "))
}

/// The chain as a planar arm under the file's gravity `g` (in the base frame; `None` when the
/// struct gives its own).
pub fn planar(chain: &Chain, file: &str, g: Option<&Vec3>) -> Result<Planar, FileError> {
    let fail = |joint: &str, what: String| FileError(format!("{file}: joint `{joint}`: {what}"));
    // Each joint's frame at q = 0 in the base's, its axis there, and the tool's.
    let mut frames: Vec<Pose> = Vec::new();
    let mut at = Pose::identity();
    for j in &chain.joints {
        at = at.then(&j.origin);
        frames.push(at.clone());
    }
    let tool = at.then(&chain.tool);
    let axes: Vec<Vec3> = chain
        .joints
        .iter()
        .zip(&frames)
        .map(|(j, w)| w.rotation().apply(&j.joint.axis))
        .collect();
    let name = |i: usize| chain.joints[i].joint.name.as_str();
    let hinge = |i: usize| chain.joints[i].joint.kind == JointKind::Revolute;
    let first = (0..axes.len()).find(|&i| hinge(i)).ok_or_else(|| {
        FileError(format!(
            "{file}: no hinge fixes the plane of a planar arm; read the file with \
             #[derive(SpatialArm)]"
        ))
    })?;
    let n = unit(&axes[first]);
    for (i, a) in axes.iter().enumerate() {
        let scale = norm(a);
        if hinge(i) {
            let off = cross(a, &n);
            if !negligible(&off, scale) {
                let angle = (norm(&off) / scale).asin().to_degrees();
                return Err(fail(
                    name(i),
                    format!(
                        "its axis {} leaves the plane of `{}`'s {} by {angle:.3} degrees: the \
                         model is not planar; read it with #[derive(SpatialArm)]",
                        show(a),
                        name(first),
                        show(&n)
                    ),
                ));
            }
        } else if !small(&dot(a, &n), scale) {
            return Err(fail(
                name(i),
                format!(
                    "the slide {} leaves the plane by {}",
                    show(a),
                    f(&dot(a, &n)) / scale
                ),
            ));
        }
    }
    // The plane's x: the line of the joints at q = 0.
    let anchors: Vec<Vec3> = frames.iter().map(|w| w.xyz.clone()).collect();
    let in_plane = |v: &Vec3| -> Vec3 {
        let along = dot(v, &n);
        core::array::from_fn(|i| &v[i] - &along * &n[i])
    };
    let size = anchors
        .iter()
        .chain(core::iter::once(&tool.xyz))
        .map(norm)
        .fold(1e-3_f64, f64::max);
    // The plane's x: the first link's own, so that the first joint has no offset (a first
    // slide's axis), else the first step between joints, any slide, the step to the tool.
    let first_slide = (!hinge(0)).then(|| in_plane(&axes[0]));
    let direction = first_slide
        .into_iter()
        .chain((1..anchors.len()).map(|i| in_plane(&sub(&anchors[i], &anchors[i - 1]))))
        .chain(
            (0..axes.len())
                .filter(|&i| !hinge(i))
                .map(|i| axes[i].clone()),
        )
        .chain(core::iter::once(in_plane(&sub(
            &tool.xyz,
            &anchors[anchors.len() - 1],
        ))))
        .find(|v| !negligible(v, size));
    let x = match direction {
        Some(v) => unit(&v),
        // Every joint at one point and no slide: any direction in the plane.
        None => {
            let k = (0..3).find(|&k| n[k].is_zero()).unwrap_or(0);
            let mut e: Vec3 = Default::default();
            e[k] = int(1);
            unit(&in_plane(&e))
        }
    };
    let y = cross(&n, &x);
    // Each link's x at q = 0: toward the next joint (or the tool), along the slide for a
    // slide, else the previous link's; its joint's offset the turn from the previous link's.
    let mut before = x.clone();
    let mut turned = Vec::new();
    let mut links = Vec::new();
    for (i, j) in chain.joints.iter().enumerate() {
        let end = anchors.get(i + 1).unwrap_or(&tool.xyz);
        let step = in_plane(&sub(end, &anchors[i]));
        let u = if hinge(i) {
            if negligible(&step, size) {
                before.clone()
            } else {
                unit(&step)
            }
        } else {
            let a = unit(&in_plane(&axes[i]));
            if !negligible(&cross(&step, &a), size) {
                return Err(fail(
                    name(i),
                    format!(
                        "the next joint is {} off the slide's line {}: a planar link's next \
                         joint lies along its slide",
                        norm(&cross(&step, &a)),
                        show(&a)
                    ),
                ));
            }
            a
        };
        let v = cross(&n, &u);
        let offset = offset_between(&before, &u, &n);
        if let Some(o) = &offset {
            turned.push(format!("`{}` by {o}", name(i)));
        }
        let reversed = hinge(i) && dot(&axes[i], &n).is_negative();
        let body = j.body.moved(&Pose {
            xyz: Default::default(),
            rpy: frames[i].rpy.clone(),
        });
        let c = body.com.clone();
        let [xx, yy, zz, xy, xz, yz] = body.inertia.clone();
        let tensor = [
            [xx, xy.clone(), xz.clone()],
            [xy, yy, yz.clone()],
            [xz, yz, zz],
        ];
        let about_n: Rational = (0..3)
            .flat_map(|a| (0..3).map(move |b| (a, b)))
            .map(|(a, b)| &n[a] * &tensor[a][b] * &n[b])
            .sum();
        links.push(LinkSpec {
            length: Poly::constant(dot(&step, &u)),
            mass: Poly::constant(body.mass.clone()),
            inertia: Poly::constant(about_n),
            com: (Poly::constant(dot(&c, &u)), Poly::constant(dot(&c, &v))),
            armature: Poly::constant(j.joint.armature.clone()),
            damping: Poly::constant(j.joint.damping.clone()),
            frictionloss: Poly::constant(j.joint.frictionloss.clone()),
            stiffness: Poly::constant(j.joint.stiffness.clone()),
            springref: Poly::constant(j.joint.springref.clone()),
            joint: j.joint.kind,
            range: j.joint.range.clone(),
            offset: offset.map(|angle| {
                let (cos, sin) = angle.cos_sin();
                Offset { angle, cos, sin }
            }),
            reversed,
        });
        before = u;
    }
    let mut notes = vec![format!(
        "Read as a planar arm in the plane through the first joint with normal {} (the first \
         hinge's axis), x along {} and y = n x x: a joint's angle is its qpos, each link's x \
         points toward the next joint at qpos = 0 (a slide's along the slide), its length the \
         distance to it; the tip (the end of the last link) is the tip body's frame origin.",
        show(&n),
        show(&x)
    )];
    if !turned.is_empty() {
        notes.push(format!(
            "Joints whose link turns from the previous one's at qpos = 0 (`offset`): {}.",
            turned.join(", ")
        ));
    }
    let reversed: Vec<&str> = (0..links.len())
        .filter(|&i| links[i].reversed)
        .map(name)
        .collect();
    if !reversed.is_empty() {
        notes.push(format!(
            "Hinges about -n, `reversed`: {}.",
            reversed.join(", ")
        ));
    }
    let zero = || Poly::constant(int(0));
    let Some(g) = g else {
        return Ok(Planar {
            links,
            gravity: (zero(), zero()),
            notes,
        });
    };
    // Gravity's parts in the plane: a part below rounding (a plane axis carried as decimals)
    // is zero, so that gravity along an axis stays exact.
    let gscale = norm(g);
    let part = |axis: &Vec3| {
        let r = dot(g, axis);
        if small(&r, gscale) {
            int(0)
        } else {
            r
        }
    };
    let gravity = (part(&x), part(&y));
    notes.push(format!(
        "Gravity {} in the file is ({}, {}) in the plane's frame.",
        show(g),
        f(&gravity.0),
        f(&gravity.1)
    ));
    if !small(&dot(g, &n), gscale) {
        notes.push(format!(
            "Gravity's part along the hinges' axis, {}, does no work on a planar arm and is dropped.",
            f(&dot(g, &n))
        ));
    }
    Ok(Planar {
        links,
        gravity: (Poly::constant(gravity.0), Poly::constant(gravity.1)),
        notes,
    })
}
