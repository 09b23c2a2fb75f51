//! Straight-line programs of a spatial arm's kinematics and gravity, by products of the joints'
//! transformations: each joint's constant parts and its motion (one sine-cosine pair, or the
//! slide) multiplied out base to tip, with constants 0 and 1 folded and common products shared.
//! The expanded formulas of the same functions (`mechanics::spatial::frames`) are the other
//! form; `methods::spatial` keeps the cheaper.

use crate::algebra::expr::Expr;
use crate::algebra::poly::Poly;
use crate::mechanics::planar::JointKind;
use crate::mechanics::spatial::frames::{joint_parts, link_bodies, motion, tool_frame, Frame};
use crate::mechanics::spatial::spec::SpatialArmSpec;
use crate::programs::method::Method;
use crate::slp::{Id, Program};

/// A frame whose entries are program nodes.
#[derive(Clone, Copy)]
pub(crate) struct Nodes {
    pub(crate) r: [[Id; 3]; 3],
    pub(crate) p: [Id; 3],
}

impl Nodes {
    pub(crate) fn of(p: &mut Program, f: &Frame) -> Self {
        let mut node = |e: &Expr<Poly>| p.expr(e);
        let r = core::array::from_fn(|i| core::array::from_fn(|j| node(&f.r[i][j])));
        let t = core::array::from_fn(|i| node(&f.p[i]));
        Self { r, p: t }
    }

    fn mul(&self, p: &mut Program, other: &Self) -> Self {
        let r = core::array::from_fn(|i| {
            core::array::from_fn(|j| {
                let terms: Vec<Id> = (0..3).map(|k| p.mul(self.r[i][k], other.r[k][j])).collect();
                sum(p, &terms)
            })
        });
        let t = self.apply(p, &other.p);
        Self { r, p: t }
    }

    pub(crate) fn rotate(&self, p: &mut Program, v: &[Id; 3]) -> [Id; 3] {
        core::array::from_fn(|i| {
            let terms: Vec<Id> = (0..3).map(|k| p.mul(self.r[i][k], v[k])).collect();
            sum(p, &terms)
        })
    }

    /// `r^T v`: a vector of the outer frame in this frame's axes.
    pub(crate) fn rotate_back(&self, p: &mut Program, v: &[Id; 3]) -> [Id; 3] {
        core::array::from_fn(|i| {
            let terms: Vec<Id> = (0..3).map(|k| p.mul(self.r[k][i], v[k])).collect();
            sum(p, &terms)
        })
    }

    fn apply(&self, p: &mut Program, v: &[Id; 3]) -> [Id; 3] {
        let r = self.rotate(p, v);
        core::array::from_fn(|i| p.add(r[i], self.p[i]))
    }
}

pub(crate) fn sum(p: &mut Program, terms: &[Id]) -> Id {
    let mut acc = terms[0];
    for t in &terms[1..] {
        acc = p.add(acc, *t);
    }
    acc
}

pub(crate) fn cross(p: &mut Program, a: &[Id; 3], b: &[Id; 3]) -> [Id; 3] {
    core::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let x = p.mul(a[j], b[k]);
        let y = p.mul(a[k], b[j]);
        p.sub(x, y)
    })
}

pub(crate) fn dot(p: &mut Program, a: &[Id; 3], b: &[Id; 3]) -> Id {
    let terms: Vec<Id> = (0..3).map(|i| p.mul(a[i], b[i])).collect();
    sum(p, &terms)
}

/// The arm multiplied out in one program: each link's frame, each joint's axis (a point on it
/// and its direction), the tool frame.
struct Chain {
    links: Vec<Nodes>,
    axes: Vec<([Id; 3], [Id; 3])>,
    tool: Nodes,
}

fn chain(p: &mut Program, arm: &SpatialArmSpec) -> Chain {
    let mut frame: Option<Nodes> = None;
    let (mut links, mut axes) = (Vec::new(), Vec::new());
    for (j, joint) in arm.joints.iter().enumerate() {
        let (pre, axis, post) = joint_parts(joint);
        let pre = Nodes::of(p, &pre);
        let at_axis = match &frame {
            Some(f) => f.mul(p, &pre),
            None => pre,
        };
        let u: [Id; 3] = core::array::from_fn(|i| p.poly(&axis[i]));
        let direction = at_axis.rotate(p, &u);
        axes.push((at_axis.p, direction));
        let moved = Nodes::of(p, &motion(joint.kind, &axis, j));
        let post = Nodes::of(p, &post);
        let next = at_axis.mul(p, &moved).mul(p, &post);
        links.push(next);
        frame = Some(next);
    }
    let tool_frame = tool_frame(arm);
    let tool_nodes = Nodes::of(p, &tool_frame);
    let tool = match &frame {
        Some(f) => f.mul(p, &tool_nodes),
        None => tool_nodes,
    };
    Chain { links, axes, tool }
}

fn frame_outputs(prefix: &str, f: &Nodes, out: &mut Vec<(String, Id)>) {
    for i in 0..3 {
        for j in 0..3 {
            out.push((format!("{prefix}r{}{}", i + 1, j + 1), f.r[i][j]));
        }
    }
    for i in 0..3 {
        out.push((format!("{prefix}p{}", i + 1), f.p[i]));
    }
}

/// The tool pose: rotation row-major, then position (12 outputs).
#[must_use]
pub fn tip_pose(arm: &SpatialArmSpec) -> Method {
    let mut p = Program::new();
    let c = chain(&mut p, arm);
    let mut out = Vec::new();
    frame_outputs("", &c.tool, &mut out);
    Method::new(p, out).described("the joints' transformations multiplied out base to tip")
}

/// Every link's pose, 12 outputs each, base first.
#[must_use]
pub fn link_poses(arm: &SpatialArmSpec) -> Method {
    let mut p = Program::new();
    let c = chain(&mut p, arm);
    let mut out = Vec::new();
    for (i, l) in c.links.iter().enumerate() {
        frame_outputs(&format!("l{}", i + 1), l, &mut out);
    }
    Method::new(p, out).described("the joints' transformations multiplied out base to tip")
}

/// The geometric Jacobian, row-major (6 x N): column `i` is `(z x (p - o), z)` for a hinge and
/// `(z, 0)` for a slide, from each joint's axis `(o, z)` and the tool origin `p`.
#[must_use]
pub fn jacobian(arm: &SpatialArmSpec) -> Method {
    let mut p = Program::new();
    let c = chain(&mut p, arm);
    let n = arm.joints.len();
    let zero = p.constant(crate::algebra::ring::int(0));
    let mut columns = Vec::with_capacity(n);
    for (i, joint) in arm.joints.iter().enumerate() {
        let (o, z) = c.axes[i];
        let column: [Id; 6] = match joint.kind {
            JointKind::Revolute => {
                let arm_to_tip: [Id; 3] = core::array::from_fn(|k| p.sub(c.tool.p[k], o[k]));
                let v = cross(&mut p, &z, &arm_to_tip);
                [v[0], v[1], v[2], z[0], z[1], z[2]]
            }
            JointKind::Prismatic => [z[0], z[1], z[2], zero, zero, zero],
        };
        columns.push(column);
    }
    let mut out = Vec::with_capacity(6 * n);
    for r in 0..6 {
        for (i, column) in columns.iter().enumerate() {
            out.push((format!("j{}{}", r + 1, i + 1), column[r]));
        }
    }
    Method::new(p, out).described("each joint's axis from the product of transformations, crossed with the arm to the tool origin")
}

/// The gravity torques, by composite masses from the tip: with `M_i` the mass beyond joint `i`
/// and `C_i` the sum of those masses times their centres, `g_i = -z_i . ((C_i - M_i o_i) x g)`
/// for a hinge and `-M_i z_i . g` for a slide; and the potential energy `-g . C_1`.
#[must_use]
pub fn gravity(arm: &SpatialArmSpec) -> (Method, Method) {
    let (g_method, v_method) = (Program::new(), Program::new());
    (
        gravity_program(arm, g_method, true),
        gravity_program(arm, v_method, false),
    )
}

fn gravity_program(arm: &SpatialArmSpec, mut p: Program, torques: bool) -> Method {
    let c = chain(&mut p, arm);
    let n = arm.joints.len();
    let g: [Id; 3] = core::array::from_fn(|i| p.poly(&arm.gravity[i]));
    let zero = p.constant(crate::algebra::ring::int(0));
    let (mut mass, mut moment) = (zero, [zero; 3]);
    let mut out = vec![(String::new(), zero); n];
    for i in (0..n).rev() {
        let joint = &arm.joints[i];
        for body in link_bodies(arm, i) {
            let m = p.poly(&body.mass);
            let com: [Id; 3] = core::array::from_fn(|k| p.poly(&body.com[k]));
            let centre = c.links[i].apply(&mut p, &com);
            mass = p.add(mass, m);
            moment = core::array::from_fn(|k| {
                let x = p.mul(m, centre[k]);
                p.add(moment[k], x)
            });
        }
        let (o, z) = c.axes[i];
        let value = match joint.kind {
            JointKind::Revolute => {
                let arm_moment: [Id; 3] = core::array::from_fn(|k| {
                    let mo = p.mul(mass, o[k]);
                    p.sub(moment[k], mo)
                });
                let torque = cross(&mut p, &arm_moment, &g);
                let d = dot(&mut p, &z, &torque);
                p.neg(d)
            }
            JointKind::Prismatic => {
                let d = dot(&mut p, &z, &g);
                let f = p.mul(mass, d);
                p.neg(f)
            }
        };
        let value = match crate::programs::spatial_newton_euler::spring(&mut p, arm, i) {
            Some(s) => p.add(value, s),
            None => value,
        };
        out[i] = (format!("g{}", i + 1), value);
    }
    if torques {
        Method::new(p, out)
            .described("composite masses and first moments from the tip, crossed with gravity")
    } else {
        let d = dot(&mut p, &moment, &g);
        let mut v = p.neg(d);
        if let Some(e) = crate::programs::spatial_newton_euler::spring_energy(&mut p, arm) {
            v = p.add(v, e);
        }
        Method::new(p, vec![("v".to_string(), v)])
            .described("the first moment of every link's mass, dotted with gravity")
    }
}
