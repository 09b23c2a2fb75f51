//! Writing a spatial arm as a model file MuJoCo (MJCF) or Pinocchio and ROS (URDF) load, and
//! that `#[derive(SpatialArm)]` reads back.
//!
//! Each joint is `pre * motion(q) * post` ([`JointGeometry`]): a file's body (or link) frame
//! is the frame after the motion, so a body sits at the previous joint's `post` times this
//! joint's `pre`, and a link's mass properties are placed by `post`. Numbers are written as
//! the shortest decimals that read back to the same `f64`; angles in degrees, exactly where
//! they are multiples of a degree (`pi/2` as `90`), so that an arm of right-angle twists reads
//! back with exact twists.

use std::fmt::Write as _;
use std::string::String;
use std::vec::Vec;

use nalgebra::{Matrix3, Vector3};

use super::{JointGeometry, SpatialLink, SpatialModel};
use crate::Joint;

/// `cos` and `sin`, exact at multiples of `pi/2` (where `f64` would give `6e-17`).
fn cos_sin(a: f64) -> (f64, f64) {
    let quarter = a / core::f64::consts::FRAC_PI_2;
    let k = quarter.round();
    if (quarter - k).abs() < 1e-15 * quarter.abs().max(1.0) {
        #[allow(clippy::cast_possible_truncation)] // |k| is small: a checked angle
        return match (k as i64).rem_euclid(4) {
            0 => (1.0, 0.0),
            1 => (0.0, 1.0),
            2 => (-1.0, 0.0),
            _ => (0.0, -1.0),
        };
    }
    (a.cos(), a.sin())
}

/// A rigid transformation `p + R x`.
#[derive(Clone, Copy)]
struct Frame {
    r: Matrix3<f64>,
    p: Vector3<f64>,
}

impl Frame {
    const IDENTITY: Self = Self {
        r: Matrix3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
        p: Vector3::new(0.0, 0.0, 0.0),
    };

    fn shift(x: f64, y: f64, z: f64) -> Self {
        Self {
            p: Vector3::new(x, y, z),
            ..Self::IDENTITY
        }
    }

    fn rot(axis: usize, a: f64) -> Self {
        let (c, s) = cos_sin(a);
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        let mut r = Matrix3::identity();
        r[(i, i)] = c;
        r[(j, j)] = c;
        r[(j, i)] = s;
        r[(i, j)] = -s;
        Self {
            r,
            ..Self::IDENTITY
        }
    }

    fn then(&self, o: &Self) -> Self {
        Self {
            r: self.r * o.r,
            p: self.p + self.r * o.p,
        }
    }
}

/// A joint as `pre`, the axis its motion is about or along (in the frame after `pre`), and
/// `post`; with the angles that write `pre`'s rotation and `post`'s (for the orientation
/// attributes), about x, y, z in turn for `dh`/`mdh` (`Rx Rz`) and as `Rz Ry Rx` for `origin`.
struct Split {
    pre: Frame,
    axis: Vector3<f64>,
    post: Frame,
}

fn split(g: &JointGeometry, kind: Joint) -> Split {
    let z = Vector3::z();
    match *g {
        JointGeometry::Dh { a, alpha, d, theta } => Split {
            pre: Frame::rot(2, theta),
            axis: z,
            post: Frame::shift(0.0, 0.0, d)
                .then(&Frame::shift(a, 0.0, 0.0))
                .then(&Frame::rot(0, alpha)),
        },
        JointGeometry::Mdh { a, alpha, d, theta } => {
            let pre = Frame::rot(0, alpha)
                .then(&Frame::shift(a, 0.0, 0.0))
                .then(&Frame::rot(2, theta));
            let along = Frame::shift(0.0, 0.0, d);
            match kind {
                Joint::Revolute => Split {
                    pre,
                    axis: z,
                    post: along,
                },
                Joint::Prismatic => Split {
                    pre: pre.then(&along),
                    axis: z,
                    post: Frame::IDENTITY,
                },
            }
        }
        JointGeometry::Urdf { xyz, rpy, axis } => Split {
            pre: Frame::shift(xyz.x, xyz.y, xyz.z)
                .then(&Frame::rot(2, rpy.z))
                .then(&Frame::rot(1, rpy.y))
                .then(&Frame::rot(0, rpy.x)),
            axis: axis.try_normalize(0.0).unwrap_or(z),
            post: Frame::IDENTITY,
        },
    }
}

/// The shortest decimal that reads back to `x`.
fn num(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-4..1e9).contains(&a) {
        std::format!("{x}")
    } else {
        std::format!("{x:e}")
    }
}

fn nums(v: &[f64]) -> String {
    v.iter().map(|x| num(*x)).collect::<Vec<_>>().join(" ")
}

/// Degrees, exact where the angle is a whole number of millionths of a degree in `f64`.
fn degrees(a: f64) -> String {
    let d = a.to_degrees();
    let r = (d * 1e6).round() / 1e6;
    if (r.to_radians() - a).abs() <= 4.0 * f64::EPSILON * a.abs() {
        num(r)
    } else {
        num(d)
    }
}

/// Roll, pitch, yaw of `r = Rz(y) Ry(p) Rx(r)`.
fn rpy(r: &Matrix3<f64>) -> [f64; 3] {
    let pitch = (-r[(2, 0)]).atan2(r[(0, 0)].hypot(r[(1, 0)]));
    if r[(0, 0)].hypot(r[(1, 0)]) < 1e-12 {
        return [0.0, pitch, (-r[(0, 1)]).atan2(r[(1, 1)])];
    }
    [
        r[(2, 1)].atan2(r[(2, 2)]),
        pitch,
        r[(1, 0)].atan2(r[(0, 0)]),
    ]
}

/// A link's mass properties seen from a frame in which its own is `at`.
fn placed(link: &SpatialLink, at: &Frame) -> (Vector3<f64>, Matrix3<f64>) {
    (
        at.p + at.r * link.com,
        at.r * link.inertia * at.r.transpose(),
    )
}

/// Whether the principal moments of `i` break `A + B >= C`: `tr(I)/2 E - I`, the second
/// moment of the mass, is not positive semi-definite.
fn breaks_triangle(i: &Matrix3<f64>) -> bool {
    let c = Matrix3::identity() * (i.trace() / 2.0) - i;
    let tol = 1e-12 * i.amax();
    c.symmetric_eigenvalues().iter().any(|e| *e < -tol)
}

/// The arm as MJCF: one body per link, nested, `q` equal to MuJoCo's `qpos`.
#[must_use]
pub fn mjcf<const N: usize>(model: &SpatialModel<N>, names: &[&str; N], name: &str) -> String {
    let mut out = String::new();
    let mut body = String::new();
    let mut before = Frame::IDENTITY;
    let mut unbalanced = Vec::new();
    let mut depth = 2;
    let pad = |d: usize| "  ".repeat(d);
    for (k, (joint, link)) in model.joints.iter().zip(&model.links).enumerate() {
        let s = split(&joint.geometry, joint.kind);
        let at = before.then(&s.pre);
        let [r, p, y] = rpy(&at.r);
        let _ = writeln!(
            body,
            "{}<body name=\"{}_link\" pos=\"{}\" euler=\"{} {} {}\">",
            pad(depth),
            names[k],
            nums(at.p.as_slice()),
            degrees(y),
            degrees(p),
            degrees(r)
        );
        let kind = match joint.kind {
            Joint::Revolute => "hinge",
            Joint::Prismatic => "slide",
        };
        let mut extra = String::new();
        if let Some((lo, hi)) = joint.range {
            let (lo, hi) = match joint.kind {
                Joint::Revolute => (degrees(lo), degrees(hi)),
                Joint::Prismatic => (num(lo), num(hi)),
            };
            let _ = write!(extra, " range=\"{lo} {hi}\"");
        }
        let springref = match joint.kind {
            Joint::Revolute => degrees(joint.springref),
            Joint::Prismatic => num(joint.springref),
        };
        if joint.stiffness != 0.0 && joint.springref != 0.0 {
            let _ = write!(extra, " springref=\"{springref}\"");
        }
        for (key, v) in [
            ("armature", joint.armature),
            ("damping", joint.damping),
            ("frictionloss", joint.frictionloss),
            ("stiffness", joint.stiffness),
        ] {
            if v != 0.0 {
                let _ = write!(extra, " {key}=\"{}\"", num(v));
            }
        }
        let _ = writeln!(
            body,
            "{}<joint name=\"{}\" type=\"{kind}\" axis=\"{}\"{extra}/>",
            pad(depth + 1),
            names[k],
            nums(s.axis.as_slice())
        );
        let (held, com, inertia) = carried(model, k, link, &s.post);
        if breaks_triangle(&inertia) {
            unbalanced.push(names[k]);
        }
        let _ = writeln!(
            body,
            "{}<inertial pos=\"{}\" mass=\"{}\" fullinertia=\"{}\"/>",
            pad(depth + 1),
            nums(com.as_slice()),
            num(held.mass),
            nums(&[
                inertia[(0, 0)],
                inertia[(1, 1)],
                inertia[(2, 2)],
                inertia[(0, 1)],
                inertia[(0, 2)],
                inertia[(1, 2)]
            ])
        );
        before = s.post;
        depth += 1;
    }
    let t = before.then(&tool_frame(model));
    let [r, p, y] = rpy(&t.r);
    let _ = writeln!(
        body,
        "{}<body name=\"tool\" pos=\"{}\" euler=\"{} {} {}\"/>",
        pad(depth),
        nums(t.p.as_slice()),
        degrees(y),
        degrees(p),
        degrees(r)
    );
    for d in (2..depth).rev() {
        let _ = writeln!(body, "{}</body>", pad(d));
    }
    let _ = writeln!(out, "<mujoco model=\"{name}\">");
    let _ = writeln!(
        out,
        "  <!-- Written by planar_arm: q is qpos; the tip is the body `tool`. -->"
    );
    let balance = if unbalanced.is_empty() {
        String::new()
    } else {
        let _ = writeln!(
            out,
            "  <!-- balanceinertia: MuJoCo refuses inertias that break the triangle inequality, \
             as these links' do: {}; with balanceinertia it uses each one's mean principal \
             moment about every axis instead. -->",
            unbalanced.join(", ")
        );
        " balanceinertia=\"true\"".into()
    };
    let _ = writeln!(
        out,
        "  <compiler angle=\"degree\" eulerseq=\"zyx\" autolimits=\"true\"{balance}/>"
    );
    let _ = writeln!(
        out,
        "  <option gravity=\"{}\"/>",
        nums(model.gravity.as_slice())
    );
    let _ = writeln!(out, "  <worldbody>");
    out.push_str(&body);
    let _ = writeln!(out, "  </worldbody>");
    let _ = writeln!(out, "</mujoco>");
    out
}

/// The tool frame in the last link's frame.
fn tool_frame<const N: usize>(model: &SpatialModel<N>) -> Frame {
    Frame {
        r: model.tool.rotation.to_rotation_matrix().into_inner(),
        p: model.tool.translation.vector,
    }
}

/// What body `k` of a file carries, in the file's body frame (after the joint's motion; the
/// link's own frame is `post` there): the link, and on the last the payload, placed by the tool
/// frame. Its mass properties, centre of mass and tensor about it in the body's axes.
fn carried<const N: usize>(
    model: &SpatialModel<N>,
    k: usize,
    link: &SpatialLink,
    post: &Frame,
) -> (SpatialLink, Vector3<f64>, Matrix3<f64>) {
    let (held, at) = match &model.payload {
        Some(p) if k + 1 == N => (
            merge(link, post, p, &post.then(&tool_frame(model))),
            Frame::IDENTITY,
        ),
        _ => (*link, *post),
    };
    let (com, inertia) = placed(&held, &at);
    (held, com, inertia)
}

/// Two bodies merged, each placed in a common frame.
fn merge(a: &SpatialLink, at_a: &Frame, b: &SpatialLink, at_b: &Frame) -> SpatialLink {
    let (ca, ia) = placed(a, at_a);
    let (cb, ib) = placed(b, at_b);
    let m = a.mass + b.mass;
    if m == 0.0 {
        return SpatialLink {
            inertia: ia + ib,
            ..SpatialLink::MASSLESS
        };
    }
    let c = (ca * a.mass + cb * b.mass) / m;
    let shift =
        |mass: f64, d: Vector3<f64>| (Matrix3::identity() * d.dot(&d) - d * d.transpose()) * mass;
    SpatialLink {
        mass: m,
        com: c,
        inertia: ia + shift(a.mass, ca - c) + ib + shift(b.mass, cb - c),
    }
}

/// The arm as URDF: one link per joint plus `base` and `tool`. URDF holds no armature and
/// no gravity (readers assume `0 0 -9.81`); what the arm has of them is said in comments.
#[must_use]
pub fn urdf<const N: usize>(model: &SpatialModel<N>, names: &[&str; N], name: &str) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "<?xml version=\"1.0\"?>");
    let _ = writeln!(out, "<robot name=\"{name}\">");
    let _ = writeln!(
        out,
        "  <!-- Written by planar_arm: joint values are q; the tip is the link `tool`. -->"
    );
    for (what, has) in [
        (
            "armature",
            (|j: &super::SpatialJoint| j.armature != 0.0) as fn(&_) -> bool,
        ),
        ("spring", |j: &super::SpatialJoint| j.stiffness != 0.0),
    ] {
        let which: Vec<&str> = model
            .joints
            .iter()
            .zip(names)
            .filter(|(j, _)| has(j))
            .map(|(_, n)| *n)
            .collect();
        if !which.is_empty() {
            let _ = writeln!(
                out,
                "  <!-- Not written, as URDF cannot hold it: the {what} of {}. -->",
                which.join(", ")
            );
        }
    }
    if model.gravity != Vector3::new(0.0, 0.0, -9.81) {
        let _ = writeln!(
            out,
            "  <!-- Not written, as URDF cannot hold it: gravity {}. -->",
            nums(model.gravity.as_slice())
        );
    }
    let _ = writeln!(out, "  <link name=\"base\"/>");
    let mut parent = String::from("base");
    let mut before = Frame::IDENTITY;
    for (k, (joint, link)) in model.joints.iter().zip(&model.links).enumerate() {
        let s = split(&joint.geometry, joint.kind);
        let at = before.then(&s.pre);
        let child = std::format!("{}_link", names[k]);
        let (held, com, i) = carried(model, k, link, &s.post);
        let _ = writeln!(out, "  <link name=\"{child}\">");
        let _ = writeln!(
            out,
            "    <inertial>\n      <origin xyz=\"{}\" rpy=\"0 0 0\"/>\n      <mass value=\"{}\"/>\n      \
             <inertia ixx=\"{}\" ixy=\"{}\" ixz=\"{}\" iyy=\"{}\" iyz=\"{}\" izz=\"{}\"/>\n    </inertial>",
            nums(com.as_slice()),
            num(held.mass),
            num(i[(0, 0)]),
            num(i[(0, 1)]),
            num(i[(0, 2)]),
            num(i[(1, 1)]),
            num(i[(1, 2)]),
            num(i[(2, 2)])
        );
        let _ = writeln!(out, "  </link>");
        let kind = match (joint.kind, joint.range) {
            (Joint::Revolute, None) => "continuous",
            (Joint::Revolute, Some(_)) => "revolute",
            (Joint::Prismatic, _) => "prismatic",
        };
        let [r, p, y] = rpy(&at.r);
        let _ = writeln!(out, "  <joint name=\"{}\" type=\"{kind}\">", names[k]);
        let _ = writeln!(
            out,
            "    <parent link=\"{parent}\"/>\n    <child link=\"{child}\"/>"
        );
        let _ = writeln!(
            out,
            "    <origin xyz=\"{}\" rpy=\"{}\"/>\n    <axis xyz=\"{}\"/>",
            nums(at.p.as_slice()),
            nums(&[r, p, y]),
            nums(s.axis.as_slice())
        );
        let (lo, hi) = joint.range.unwrap_or((-1e9, 1e9));
        if joint.range.is_some() || joint.kind == Joint::Prismatic {
            let _ = writeln!(
                out,
                "    <limit lower=\"{}\" upper=\"{}\" effort=\"0\" velocity=\"0\"/>",
                num(lo),
                num(hi)
            );
        }
        if joint.damping != 0.0 || joint.frictionloss != 0.0 {
            let _ = writeln!(
                out,
                "    <dynamics damping=\"{}\" friction=\"{}\"/>",
                num(joint.damping),
                num(joint.frictionloss)
            );
        }
        let _ = writeln!(out, "  </joint>");
        parent = child;
        before = s.post;
    }
    let t = before.then(&tool_frame(model));
    let [r, p, y] = rpy(&t.r);
    let _ = writeln!(out, "  <link name=\"tool\"/>");
    let _ = writeln!(
        out,
        "  <joint name=\"tool_joint\" type=\"fixed\">\n    <parent link=\"{parent}\"/>\n    \
         <child link=\"tool\"/>\n    <origin xyz=\"{}\" rpy=\"{}\"/>\n  </joint>",
        nums(t.p.as_slice()),
        nums(&[r, p, y])
    );
    let _ = writeln!(out, "</robot>");
    out
}

/// The type's name without its path, as a model's name.
pub(crate) fn short_name<T>() -> &'static str {
    let full = core::any::type_name::<T>();
    let base = full.split('<').next().unwrap_or(full);
    base.rsplit("::").next().unwrap_or(base)
}
