//! The composite-rigid-body algorithm unrolled for one spatial arm, in the links' own frames as
//! the Newton-Euler recursion beside it (`spatial_newton_euler`), whose joints' transformations
//! it shares.
//!
//! A rigid body is held about a frame's origin in its axes: mass `m`, first moment `h = m c`
//! and rotational inertia `J = I_c + m (|c|^2 1 - c c^T)`. The composite of links `i..N` is
//! link `i`'s body plus the composite beyond, moved into link `i`'s frame: with `R` the
//! rotation and `o` the origin of link `i + 1`'s frame there and `k = R h`,
//!
//! ```text
//! h' = m o + k
//! J' = R J R^T + m (|o|^2 1 - o o^T) + 2 (o . k) 1 - o k^T - k o^T
//! ```
//!
//! Joint `i`'s unit rate moves the composite with the momentum `F = (J w + h x v, m v + w x h)`
//! (`w`, `v` the rate's angular and origin velocity: `z_i` and `z_i x r_i` for a hinge, `0`
//! and `z_i` for a slide); `M_ii` is `F` read on joint `i`'s axis and `M_ji` the same force
//! carried inwards to joint `j` as the Newton-Euler recursion carries forces.

use crate::algebra::ring::int;
use crate::mechanics::planar::JointKind;
use crate::mechanics::spatial::frames::link_bodies;
use crate::mechanics::spatial::spec::{SpatialArmSpec, SpatialBody};
use crate::programs::method::{two, Method};
use crate::programs::spatial::{cross, dot};
use crate::programs::spatial_newton_euler::{add, scale, Joint, V3};
use crate::slp::{Id, Input, Program};

/// A rigid body about a frame's origin, in its axes.
#[derive(Clone, Copy)]
struct Body {
    m: Id,
    h: V3,
    j: [[Id; 3]; 3],
}

#[allow(clippy::needless_range_loop)] // the indices are the tensor's
fn symmetric(p: &mut Program, full: impl Fn(&mut Program, usize, usize) -> Id) -> [[Id; 3]; 3] {
    let mut j = [[Id(0); 3]; 3];
    for a in 0..3 {
        for b in a..3 {
            let x = full(p, a, b);
            j[a][b] = x;
            j[b][a] = x;
        }
    }
    j
}

/// `m (|o|^2 1 - o o^T) + 2 (o . k) 1 - o k^T - k o^T`, entry `(a, b)`: the parallel-axis
/// terms of a body with mass `m` and first moment `k` about a point `o` from the new origin.
fn shifted(p: &mut Program, m: Id, o: &V3, k: &V3, a: usize, b: usize) -> Id {
    let mo = scale(p, o, m);
    let (x, y) = (p.mul(mo[a], o[b]), p.mul(o[a], k[b]));
    let z = p.mul(k[a], o[b]);
    let mut e = p.neg(x);
    e = p.sub(e, y);
    e = p.sub(e, z);
    if a == b {
        let oo = dot(p, &mo, o);
        let ok = dot(p, o, k);
        let two = p.constant(int(2));
        let ok2 = p.mul(two, ok);
        e = p.add(e, oo);
        e = p.add(e, ok2);
    }
    e
}

/// The bodies link `i` carries (its own, and the payload on the last), about its frame's
/// origin.
fn own(p: &mut Program, arm: &SpatialArmSpec, i: usize) -> Body {
    let bodies: Vec<Body> = link_bodies(arm, i)
        .iter()
        .map(|body| about_origin(p, body))
        .collect();
    bodies
        .into_iter()
        .reduce(|a, b| sum_bodies(p, &a, &b))
        .unwrap_or_else(|| unreachable!("a link carries its own body"))
}

fn sum_bodies(p: &mut Program, a: &Body, b: &Body) -> Body {
    Body {
        m: p.add(a.m, b.m),
        h: add(p, &a.h, &b.h),
        j: core::array::from_fn(|r| core::array::from_fn(|c| p.add(a.j[r][c], b.j[r][c]))),
    }
}

/// One body about its frame's origin.
fn about_origin(p: &mut Program, spec: &SpatialBody) -> Body {
    let m = p.poly(&spec.mass);
    let c: V3 = core::array::from_fn(|k| p.poly(&spec.com[k]));
    let h = scale(p, &c, m);
    let [xx, yy, zz, xy, xz, yz] = core::array::from_fn(|k| p.poly(&spec.inertia[k]));
    let about_com = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]];
    let zero = [p.constant(int(0)); 3];
    let j = symmetric(p, |p, a, b| {
        // The centre of mass at c from the origin: the parallel-axis terms with k = 0.
        let shift = shifted(p, m, &c, &zero, a, b);
        p.add(about_com[a][b], shift)
    });
    Body { m, h, j }
}

/// Where joint `i`'s link frame sits: from `A_i` to its origin, in its own axes.
fn reach(p: &mut Program, joint: &Joint, i: usize) -> V3 {
    match joint.kind {
        JointKind::Revolute => joint.r,
        JointKind::Prismatic => {
            let q = p.input(Input::Q(i));
            let along = scale(p, &joint.z, q);
            add(p, &joint.r, &along)
        }
    }
}

/// `body`, held in link `i`'s frame, moved into link `i - 1`'s.
fn moved(p: &mut Program, joint: &Joint, r: &V3, body: &Body) -> Body {
    let out = joint.outward(p, r);
    let o = add(p, &joint.pre.p, &out);
    let k = joint.outward(p, &body.h);
    let mo = scale(p, &o, body.m);
    let h = add(p, &mo, &k);
    // R J R^T: R applied to J's columns, then to the result's rows.
    let columns: [V3; 3] = core::array::from_fn(|c| {
        let col = [body.j[0][c], body.j[1][c], body.j[2][c]];
        joint.outward(p, &col)
    });
    let turned: [V3; 3] = core::array::from_fn(|row| {
        let v = [columns[0][row], columns[1][row], columns[2][row]];
        joint.outward(p, &v)
    });
    let j = symmetric(p, |p, a, b| {
        let shift = shifted(p, body.m, &o, &k, a, b);
        p.add(turned[b][a], shift)
    });
    Body { m: body.m, h, j }
}

fn sum(p: &mut Program, a: &Body, b: &Body) -> Body {
    let m = p.add(a.m, b.m);
    let h = add(p, &a.h, &b.h);
    let j = symmetric(p, |p, x, y| p.add(a.j[x][y], b.j[x][y]));
    Body { m, h, j }
}

/// `J w + h x v` and `m v + w x h`.
fn momentum(p: &mut Program, body: &Body, w: &V3, v: &V3) -> (V3, V3) {
    let jw: V3 = core::array::from_fn(|a| {
        let terms: Vec<Id> = (0..3).map(|b| p.mul(body.j[a][b], w[b])).collect();
        crate::programs::spatial::sum(p, &terms)
    });
    let hv = cross(p, &body.h, v);
    let mv = scale(p, v, body.m);
    let wh = cross(p, w, &body.h);
    (add(p, &jw, &hv), add(p, &mv, &wh))
}

/// A force (moment about the origin, force) read on joint `i`'s axis: the moment about the
/// axis for a hinge, the force along it for a slide.
fn on_axis(p: &mut Program, joint: &Joint, r: &V3, moment: &V3, force: &V3) -> Id {
    match joint.kind {
        JointKind::Revolute => {
            let shift = cross(p, r, force);
            let about = add(p, moment, &shift);
            dot(p, &joint.z, &about)
        }
        JointKind::Prismatic => dot(p, &joint.z, force),
    }
}

/// The mass matrix, row-major `N x N` (`m11`, `m12`, ...), armature on the diagonal.
pub(crate) fn mass_matrix(arm: &SpatialArmSpec) -> Method {
    let mut p = Program::new();
    let m = composite(&mut p, arm);
    let mut outputs = Vec::new();
    for (i, row) in m.iter().enumerate() {
        for (j, id) in row.iter().enumerate() {
            outputs.push((format!("m{}", two(i, j)), *id));
        }
    }
    Method::new(p, outputs).described(DESCRIPTION)
}

/// How the algorithm's methods are evaluated, for their docs.
pub(crate) const DESCRIPTION: &str = "the composite-rigid-body algorithm unrolled, each link in its own frame, the joints' constant transformations folded in";

/// [`mass_matrix`]'s entries as nodes of `p`, rows of columns.
pub(crate) fn composite(p: &mut Program, arm: &SpatialArmSpec) -> Vec<Vec<Id>> {
    let n = arm.joints.len();
    let joints: Vec<Joint> = (0..n).map(|j| Joint::new(p, arm, j)).collect();
    let reaches: Vec<V3> = (0..n).map(|i| reach(p, &joints[i], i)).collect();
    // Composites from the tip.
    let mut composites: Vec<Option<Body>> = vec![None; n];
    for i in (0..n).rev() {
        let body = own(p, arm, i);
        composites[i] = Some(match composites.get(i + 1).copied().flatten() {
            Some(beyond) => {
                let beyond = moved(p, &joints[i + 1], &reaches[i + 1], &beyond);
                sum(p, &body, &beyond)
            }
            None => body,
        });
    }
    let zero = p.constant(int(0));
    let mut m = vec![vec![zero; n]; n];
    for i in 0..n {
        let body = composites[i].expect("every composite formed");
        let joint = &joints[i];
        let (w, v) = match joint.kind {
            JointKind::Revolute => (joint.z, cross(p, &joint.z, &reaches[i])),
            JointKind::Prismatic => ([zero; 3], joint.z),
        };
        let (mut moment, mut force) = momentum(p, &body, &w, &v);
        let own = on_axis(p, joint, &reaches[i], &moment, &force);
        let armature = p.poly(&arm.joints[i].armature);
        m[i][i] = p.add(own, armature);
        for k in (0..i).rev() {
            // Carried from link k + 1's frame to link k's, about its origin.
            let carrier = &joints[k + 1];
            let shift = cross(p, &reaches[k + 1], &force);
            let about_axis = add(p, &moment, &shift);
            force = carrier.outward(p, &force);
            let back = carrier.outward(p, &about_axis);
            let lever = cross(p, &carrier.pre.p, &force);
            moment = add(p, &back, &lever);
            let value = on_axis(p, &joints[k], &reaches[k], &moment, &force);
            m[k][i] = value;
            m[i][k] = value;
        }
    }
    m
}

/// The mass matrix (row-major) and the bias `c + g + f` in one program, sharing the joints'
/// trigonometry and transformations: what `mass_matrix_and_bias` and `forward_dynamics` read.
pub(crate) fn mass_matrix_and_bias(arm: &SpatialArmSpec) -> Method {
    let mut p = Program::new();
    let m = composite(&mut p, arm);
    let h = crate::programs::spatial_newton_euler::newton_euler(
        &mut p,
        arm,
        crate::programs::unrolled::Terms::BIAS,
        true,
    );
    let mut outputs = Vec::new();
    for (i, row) in m.iter().enumerate() {
        for (j, id) in row.iter().enumerate() {
            outputs.push((format!("m{}", two(i, j)), *id));
        }
    }
    for (i, id) in h.into_iter().enumerate() {
        outputs.push((format!("h{}", i + 1), id));
    }
    Method::new(p, outputs).described(
        "the composite-rigid-body algorithm and the recursive Newton-Euler algorithm at zero acceleration, unrolled in one program, each link in its own frame",
    )
}

/// The Coriolis matrix from Christoffel symbols of the first kind, row-major `N x N`:
/// `C_ij = sum_k (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k / 2`, the derivatives of the
/// unrolled composite-rigid-body program taken at compile time (`derivative`), so that
/// `C qd = c` and `Mdot - 2 C` is skew.
pub(crate) fn coriolis_matrix(arm: &SpatialArmSpec) -> Method {
    let mut p = Program::new();
    let m = composite(&mut p, arm);
    let n = m.len();
    let upper: Vec<(usize, usize)> = (0..n).flat_map(|i| (i..n).map(move |j| (i, j))).collect();
    let nodes: Vec<Id> = upper.iter().map(|&(i, j)| m[i][j]).collect();
    let directions: Vec<Input> = (0..n).map(Input::Q).collect();
    let derivatives = crate::programs::derivative::differentiate(&mut p, &nodes, &directions)
        .expect("the composite-rigid-body program takes no max");
    let at = |i: usize, j: usize| {
        let (a, b) = (i.min(j), i.max(j));
        upper
            .iter()
            .position(|&e| e == (a, b))
            .expect("an upper entry")
    };
    let half = p.constant(crate::algebra::ring::ratio(1, 2));
    let rates: Vec<Id> = (0..n).map(|k| p.input(Input::Qd(k))).collect();
    let mut outputs = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let mut terms = Vec::with_capacity(n);
            for (k, &rate) in rates.iter().enumerate() {
                let (a, b, c) = (
                    derivatives[at(i, j)][k],
                    derivatives[at(i, k)][j],
                    derivatives[at(j, k)][i],
                );
                let ab = p.add(a, b);
                let symbol = p.sub(ab, c);
                terms.push(p.mul(symbol, rate));
            }
            let total = crate::programs::spatial::sum(&mut p, &terms);
            outputs.push((format!("c{}", two(i, j)), p.mul(half, total)));
        }
    }
    Method::new(p, outputs).described(
        "Christoffel symbols of the unrolled composite-rigid-body program's mass matrix, differentiated at compile time",
    )
}
