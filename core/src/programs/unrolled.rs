//! Recursions unrolled for one arm: the planar recursive Newton-Euler algorithm, the
//! composite-rigid-body algorithm and an `L D L^T` solve, each written into a [`Program`] with
//! the arm's exact constants folded in. They are candidates next to the expanded formulas
//! (see [`methods`](crate::methods)).

use num_traits::{One, Signed, Zero};

use super::method::two;
use crate::expr::Expr;
use crate::mechanics::{ArmSpec, JointKind};
use crate::ring::Rational;
use crate::slp::{Emit, Id, Input, OpCount, Program};
use crate::trig::Angle;

/// Which terms of `tau = M qdd + c + g` an unrolled Newton-Euler recursion evaluates.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Terms {
    pub(crate) rates: bool,
    pub(crate) accelerations: bool,
    pub(crate) gravity: bool,
}

impl Terms {
    pub(crate) const ALL: Self = Self {
        rates: true,
        accelerations: true,
        gravity: true,
    };
    pub(crate) const CORIOLIS: Self = Self {
        rates: true,
        accelerations: false,
        gravity: false,
    };
    pub(crate) const GRAVITY: Self = Self {
        rates: false,
        accelerations: false,
        gravity: true,
    };
    pub(crate) const BIAS: Self = Self {
        rates: true,
        accelerations: false,
        gravity: true,
    };
}

/// A planar vector of program nodes.
type V2 = (Id, Id);

/// `(cos q_j, sin q_j)`: joint `j`'s own `sin_cos`.
fn joint_trig(p: &mut Program, j: usize) -> V2 {
    p.trig_pair(&Angle::range(j, j + 1))
}

/// `(cos, sin)` of `angle + o`, from those of `angle` and `turn = (cos o, sin o)`: folds to
/// `angle`'s own nodes when `o = 0`.
pub(crate) fn turn<C: Emit>(p: &mut Program, angle: (Id, Id), turn: &(C, C)) -> (Id, Id) {
    let (c, s) = angle;
    let (tc, ts) = (p.coefficient(&turn.0), p.coefficient(&turn.1));
    let (a, b) = (p.mul(c, tc), p.mul(s, ts));
    let cos = p.sub(a, b);
    let (a, b) = (p.mul(s, tc), p.mul(c, ts));
    (cos, p.add(a, b))
}

/// `R(q) v`: a vector of link `j`'s frame in link `j - 1`'s frame (`cs = (cos q_j, sin q_j)`).
fn rotate(p: &mut Program, cs: V2, v: V2) -> V2 {
    let (c, s) = cs;
    let (a, b) = (p.mul(c, v.0), p.mul(s, v.1));
    let x = p.sub(a, b);
    let (a, b) = (p.mul(s, v.0), p.mul(c, v.1));
    (x, p.add(a, b))
}

/// `R(-q) v`: a vector of link `j - 1`'s frame in link `j`'s frame.
fn rotate_back(p: &mut Program, cs: V2, v: V2) -> V2 {
    let (c, s) = cs;
    let (a, b) = (p.mul(c, v.0), p.mul(s, v.1));
    let x = p.add(a, b);
    let (a, b) = (p.mul(c, v.1), p.mul(s, v.0));
    (x, p.sub(a, b))
}

/// A link's rigid body as program nodes: mass, first moment `(hx, hy)` about the joint and
/// moment of inertia `J` about the joint, in the link's frame, the payload merged into the last.
struct BodyNodes {
    mass: Id,
    first: V2,
    inertia: Id,
}

/// The bodies' nodes, formed by node arithmetic from each value's own node rather than as
/// expanded polynomials: for a literal arm both fold to the same exact constants, but with
/// run-time parameters the products (`m cx`, then `J = I + hx cx + hy cy`) are computed once
/// and shared.
fn body_nodes<C: Emit>(p: &mut Program, arm: &ArmSpec<C>) -> Vec<BodyNodes> {
    let n = arm.links.len();
    arm.links
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let m = p.coefficient(&l.mass);
            let (cx, cy) = (p.coefficient(&l.com.0), p.coefficient(&l.com.1));
            let (hx, hy) = (p.mul(m, cx), p.mul(m, cy));
            let inertia = p.coefficient(&l.inertia);
            let (a, b) = (p.mul(hx, cx), p.mul(hy, cy));
            let ab = p.add(a, b);
            let mut body = BodyNodes {
                mass: m,
                first: (hx, hy),
                inertia: p.add(inertia, ab),
            };
            if let (Some(load), true) = (&arm.payload, i + 1 == n) {
                let mass = p.coefficient(&load.mass);
                let length = p.coefficient(&l.length);
                let ox = p.coefficient(&load.com.0);
                let px = p.add(length, ox);
                let py = p.coefficient(&load.com.1);
                let (hpx, hpy) = (p.mul(mass, px), p.mul(mass, py));
                let own = p.coefficient(&load.inertia);
                let (a, b) = (p.mul(hpx, px), p.mul(hpy, py));
                let ab = p.add(a, b);
                let extra = p.add(own, ab);
                body = BodyNodes {
                    mass: p.add(body.mass, mass),
                    first: (p.add(body.first.0, hpx), p.add(body.first.1, hpy)),
                    inertia: p.add(body.inertia, extra),
                };
            }
            body
        })
        .collect()
}

/// Joint torques by the planar recursive Newton-Euler algorithm, unrolled for the arm, in link
/// frames (x along the link): each link's angular velocity `w` and acceleration `al`, and the
/// acceleration `a` of its joint, outwards (gravity as an upward acceleration of the base);
/// the force each link's tail exerts on it and the moment about its joint, inwards. Each link
/// carries one rigid body (the payload merged into the last), and
/// each joint's rotor adds `armature qdd_i`.
pub(crate) fn newton_euler<C: Emit>(p: &mut Program, arm: &ArmSpec<C>, terms: Terms) -> Vec<Id> {
    let bodies = body_nodes(p, arm);
    let qdd: Vec<Id> = (0..arm.links.len())
        .map(|j| p.input(Input::Qdd(j)))
        .collect();
    newton_euler_of(p, arm, &bodies, None, terms, &qdd)
}

/// Which standard parameter is one in [`newton_euler_unit`].
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Unit {
    Zz(usize),
    Mx(usize),
    My(usize),
    Mass(usize),
    Armature(usize),
}

/// The torques per unit of one standard parameter: the recursion over the arm's geometry
/// carrying bodies whose parameters are all zero but `unit`, which is one. The torques are
/// linear in those parameters, so this is the parameter's regressor column; the zeros fold
/// away, and the kinematics (rotations, velocities, accelerations) are shared nodes between the
/// columns.
pub(crate) fn newton_euler_unit<C: Emit>(p: &mut Program, arm: &ArmSpec<C>, unit: Unit) -> Vec<Id> {
    let n = arm.links.len();
    let (zero, one) = (p.constant(Rational::zero()), p.constant(Rational::one()));
    let pick = |hit: bool| if hit { one } else { zero };
    let bodies: Vec<BodyNodes> = (0..n)
        .map(|i| BodyNodes {
            mass: pick(unit == Unit::Mass(i)),
            first: (pick(unit == Unit::Mx(i)), pick(unit == Unit::My(i))),
            inertia: pick(unit == Unit::Zz(i)),
        })
        .collect();
    let armature: Vec<Id> = (0..n).map(|j| pick(unit == Unit::Armature(j))).collect();
    let qdd: Vec<Id> = (0..n).map(|j| p.input(Input::Qdd(j))).collect();
    newton_euler_of(p, arm, &bodies, Some(&armature), Terms::ALL, &qdd)
}

/// The mass matrix column by column, each the recursion's torques for a unit acceleration of
/// one joint (no rates, no gravity): what an arm with prismatic joints uses in place of the
/// composite-rigid-body form, whose tail inertias assume fixed link lengths.
fn unit_acceleration_mass_matrix<C: Emit>(p: &mut Program, arm: &ArmSpec<C>) -> Vec<Vec<Id>> {
    let n = arm.links.len();
    let bodies = body_nodes(p, arm);
    let (zero, one) = (p.constant(Rational::zero()), p.constant(Rational::one()));
    let accelerations = Terms {
        rates: false,
        accelerations: true,
        gravity: false,
    };
    let columns: Vec<Vec<Id>> = (0..n)
        .map(|j| {
            let qdd: Vec<Id> = (0..n).map(|k| if k == j { one } else { zero }).collect();
            newton_euler_of(p, arm, &bodies, None, accelerations, &qdd)
        })
        .collect();
    // Symmetric: the upper triangle's nodes serve both halves.
    (0..n)
        .map(|i| (0..n).map(|j| columns[i.max(j)][i.min(j)]).collect())
        .collect()
}

fn newton_euler_of<C: Emit>(
    p: &mut Program,
    arm: &ArmSpec<C>,
    bodies: &[BodyNodes],
    armature: Option<&[Id]>,
    terms: Terms,
    qdd: &[Id],
) -> Vec<Id> {
    let n = arm.links.len();
    let zero = p.constant(Rational::zero());
    // Gravity as the base accelerating against it.
    let (gx, gy) = if terms.gravity {
        (
            p.coefficient(&-arm.gravity.0.clone()),
            p.coefficient(&-arm.gravity.1.clone()),
        )
    } else {
        (zero, zero)
    };
    let prismatic = |i: usize| arm.links[i].joint == JointKind::Prismatic;
    // A reversed joint's coordinate enters negated.
    let sensed = |p: &mut Program, i: usize, x: Id| {
        if arm.links[i].reversed {
            p.neg(x)
        } else {
            x
        }
    };
    // The constant turn of joint `i`'s frame from the previous link's, if any.
    let offset = |p: &mut Program, i: usize| {
        arm.links[i]
            .offset
            .as_ref()
            .map(|o| (p.coefficient(&o.cos), p.coefficient(&o.sin)))
    };
    // Acceleration of the current joint in the previous link's frame.
    let mut end: V2 = (gx, gy);
    let (mut w, mut al) = (zero, zero);
    // The rotation from the previous link's frame; `None` for a prismatic joint without an
    // offset, whose frame does not turn.
    let mut trig: Vec<Option<V2>> = Vec::with_capacity(n);
    let mut force = Vec::with_capacity(n);
    let mut alpha = Vec::with_capacity(n);
    let mut accel = Vec::with_capacity(n);
    for (i, (link, body)) in arm.links.iter().zip(bodies).enumerate() {
        let (cs, a) = if prismatic(i) {
            // The joint slides along its frame's x (the previous link's axis turned by the
            // offset), which turns at w: its origin accelerates by (qdd - q w^2, 2 qd w + q al)
            // there.
            let cs = offset(p, i);
            let q = p.input(Input::Q(i));
            let q = sensed(p, i, q);
            let mut a = match cs {
                Some(cs) => rotate_back(p, cs, end),
                None => end,
            };
            if terms.rates {
                let w2 = p.mul(w, w);
                let qw2 = p.mul(q, w2);
                let qd = p.input(Input::Qd(i));
                let qd = sensed(p, i, qd);
                let qdw = p.mul(qd, w);
                let two = p.constant(Rational::from_integer(2.into()));
                let coriolis = p.mul(two, qdw);
                a = (p.sub(a.0, qw2), p.add(a.1, coriolis));
            }
            if terms.accelerations {
                let qal = p.mul(q, al);
                let qdd = sensed(p, i, qdd[i]);
                a = (p.add(a.0, qdd), p.add(a.1, qal));
            }
            (cs, a)
        } else {
            let mut cs = if link.reversed {
                p.trig_pair(&Angle::new((0..=i).map(|k| -i32::from(k == i)).collect()))
            } else {
                joint_trig(p, i)
            };
            if let Some(o) = &link.offset {
                cs = turn(p, cs, &(o.cos.clone(), o.sin.clone()));
            }
            let a = rotate_back(p, cs, end);
            if terms.rates {
                let qd = p.input(Input::Qd(i));
                let qd = sensed(p, i, qd);
                w = p.add(w, qd);
                p.set_name(w, format!("w{}", i + 1));
            }
            if terms.accelerations {
                let qdd = sensed(p, i, qdd[i]);
                al = p.add(al, qdd);
                p.set_name(al, format!("al{}", i + 1));
            }
            (Some(cs), a)
        };
        p.set_name(a.0, format!("ax{}", i + 1));
        p.set_name(a.1, format!("ay{}", i + 1));
        let w2 = p.mul(w, w);
        // The force on the body, m a + (-w^2 hx - al hy, -w^2 hy + al hx) with h = m com.
        let (m, (hx, hy)) = (body.mass, body.first);
        let fx = {
            let (u, v) = (p.mul(m, a.0), p.mul(hx, w2));
            let x = p.sub(u, v);
            let t = p.mul(hy, al);
            p.sub(x, t)
        };
        let fy = {
            let (u, v) = (p.mul(m, a.1), p.mul(hx, al));
            let y = p.add(u, v);
            let t = p.mul(hy, w2);
            p.sub(y, t)
        };
        // The far end of the link: a + l (-w^2, al).
        let l = p.coefficient(&link.length);
        end = {
            let (u, v) = (p.mul(l, w2), p.mul(l, al));
            (p.sub(a.0, u), p.add(a.1, v))
        };
        p.set_name(end.0, format!("ex{}", i + 1));
        p.set_name(end.1, format!("ey{}", i + 1));
        trig.push(cs);
        force.push((fx, fy));
        alpha.push(al);
        accel.push(a);
    }
    let mut tau = vec![zero; n];
    let mut tail: Option<V2> = None;
    let mut moment = zero;
    for i in (0..n).rev() {
        let (link, body) = (&arm.links[i], &bodies[i]);
        // Moment about the joint of the body's own inertia forces: J al + hx ay - hy ax, with
        // J about the joint (the centripetal force passes through the centre of mass).
        let (inertia, (hx, hy)) = (body.inertia, body.first);
        let (u, v) = (p.mul(inertia, alpha[i]), p.mul(hx, accel[i].1));
        let mut here = p.add(u, v);
        let t = p.mul(hy, accel[i].0);
        here = p.sub(here, t);
        let mut f = force[i];
        if let Some(child) = tail {
            // The force the tail exerts at its joint, in this link's frame: at the link's far
            // end, or slid beyond it by a prismatic joint.
            let r = match trig[i + 1] {
                Some(cs) => rotate(p, cs, child),
                None => child,
            };
            let mut l = p.coefficient(&link.length);
            let mut across = None;
            if prismatic(i + 1) {
                // Slid by q along the child's axis: (cos o, sin o) in this frame.
                let q = p.input(Input::Q(i + 1));
                let q = sensed(p, i + 1, q);
                match offset(p, i + 1) {
                    None => l = p.add(l, q),
                    Some((c, s)) => {
                        let along = p.mul(q, c);
                        l = p.add(l, along);
                        across = Some(p.mul(q, s));
                    }
                }
            }
            let lever = p.mul(l, r.1);
            here = p.add(here, lever);
            if let Some(y) = across {
                let lever = p.mul(y, r.0);
                here = p.sub(here, lever);
            }
            f = (p.add(f.0, r.0), p.add(f.1, r.1));
        }
        p.set_name(f.0, format!("fx{}", i + 1));
        p.set_name(f.1, format!("fy{}", i + 1));
        moment = p.add(moment, here);
        // A revolute joint carries the moment about it, a prismatic one the force along it.
        tau[i] = if prismatic(i) { f.0 } else { moment };
        tau[i] = sensed(p, i, tau[i]);
        if terms.gravity && !link.stiffness.is_zero() {
            // The joint's spring, with the static terms: stiffness (q - springref).
            let q = p.input(Input::Q(i));
            let rest = p.coefficient(&link.springref);
            let stretch = p.sub(q, rest);
            let k = p.coefficient(&link.stiffness);
            let spring = p.mul(k, stretch);
            tau[i] = p.add(tau[i], spring);
        }
        if terms.accelerations {
            // The rotor turns with the joint's own rate: its torque is not transmitted inwards.
            let armature = match armature {
                Some(a) => a[i],
                None => p.coefficient(&link.armature),
            };
            let rotor = p.mul(armature, qdd[i]);
            tau[i] = p.add(tau[i], rotor);
        }
        tail = Some(f);
    }
    tau
}

/// The mass matrix by the composite-rigid-body algorithm, unrolled for the arm, in link frames:
/// for each tail of the chain (links `j..`), its mass, first moment `h` about joint `j` and
/// rotational inertia about joint `j` (`M_jj`, plus the joint's armature);
/// `M_ij = M_(i+1)j + l_i (h in link i's frame).x`.
pub(crate) fn composite_mass_matrix<C: Emit>(p: &mut Program, arm: &ArmSpec<C>) -> Vec<Vec<Id>> {
    if !arm.all_revolute() || !arm.plain() {
        return unit_acceleration_mass_matrix(p, arm);
    }
    let n = arm.links.len();
    let zero = p.constant(Rational::zero());
    let trig: Vec<V2> = (0..n).map(|j| joint_trig(p, j)).collect();
    let bodies = body_nodes(p, arm);
    let mut m = vec![vec![zero; n]; n];
    let mut tail_mass = zero;
    let mut tail: Option<(V2, Id)> = None;
    for j in (0..n).rev() {
        let (link, body) = (&arm.links[j], &bodies[j]);
        let l = p.coefficient(&link.length);
        // The tail beyond this link acts at the link's end: first moment `tail_mass l` and
        // moment of inertia `tail_mass l^2` about this joint.
        let tl = p.mul(tail_mass, l);
        let hx = p.add(body.first.0, tl);
        let hy = body.first.1;
        // `l^2` first: a constant when the length is one.
        let ll = p.mul(l, l);
        let tll = p.mul(tail_mass, ll);
        let rot = p.add(body.inertia, tll);
        let (h, rot) = match tail {
            None => ((hx, hy), rot),
            Some((child, child_rot)) => {
                let r = rotate(p, trig[j + 1], child);
                let two = p.constant(Rational::from_integer(2.into()));
                let two_l = p.mul(two, l);
                let shift = p.mul(two_l, r.0);
                let rot = p.add(rot, child_rot);
                ((p.add(hx, r.0), p.add(hy, r.1)), p.add(rot, shift))
            }
        };
        p.set_name(h.0, format!("hx{}", j + 1));
        p.set_name(h.1, format!("hy{}", j + 1));
        tail_mass = p.add(tail_mass, body.mass);
        let armature = p.coefficient(&link.armature);
        m[j][j] = p.add(rot, armature);
        let (mut v, mut mij) = (h, rot);
        for i in (0..j).rev() {
            v = rotate(p, trig[i + 1], v);
            let l = p.coefficient(&arm.links[i].length);
            let step = p.mul(l, v.0);
            mij = p.add(mij, step);
            m[i][j] = mij;
            m[j][i] = mij;
        }
        tail = Some((h, rot));
    }
    m
}
/// Solves `M x = b` with `M = L D L^T` unrolled (Crout's order, one multiplication per
/// inner-product term): `s_ij = M_ij - sum_k L_ik s_jk` is `L_ij d_j`, so `L_ij = s_ij / d_j`
/// and `d_i = M_ii - sum_k L_ik s_ik`; then `L y = b`, `z = y / d`, `L^T x = z`.
/// The floor under pivot `d_i` of `L D L^T`: 2^-52 times a bound on `|M_ii|` over all
/// configurations (the sum of its coefficients' magnitudes), the level of the rounding noise in
/// the computed pivot. `M` is positive definite, so its exact pivots are positive; a computed
/// one at or below the floor only means `M` is too ill-conditioned for `f64` there, and the
/// floor keeps the accelerations finite instead of infinite or NaN.
pub(crate) fn pivot_floor<C: Emit>(p: &mut Program, m_ii: &Expr<C>, m_ii_node: Id) -> Id {
    match fixed_pivot_floor(m_ii) {
        Some(floor) => p.constant(floor),
        // With run-time parameters the bound would cost a polynomial per term at every call;
        // `M_ii(q)` itself (positive, at least the exact pivot, already computed) sets the
        // same level of rounding noise for one multiplication.
        None => {
            let ulp = p.constant(ulp());
            p.mul(ulp, m_ii_node)
        }
    }
}

/// 2^-52.
fn ulp() -> Rational {
    Rational::new(1.into(), num_bigint::BigInt::from(1u64 << 52))
}

/// The floor of [`pivot_floor`] when `M_ii` has no run-time parameters: 2^-52 times the sum of
/// its coefficients' magnitudes. `None` with parameters (the floor is then 2^-52 `M_ii(q)`).
pub(crate) fn fixed_pivot_floor<C: Emit>(m_ii: &Expr<C>) -> Option<Rational> {
    let constants: Option<Vec<Rational>> = m_ii.terms().map(|(_, _, c)| c.rational()).collect();
    let bound = constants?
        .iter()
        .fold(Rational::zero(), |acc, c| acc + c.abs());
    Some(ulp() * bound)
}

/// The operations of [`ldlt_solve`] for `n` joints, with `relative` of its pivot floors
/// computed at run time (one multiplication each) and the right-hand side formed as
/// `tau - h` (one subtraction per joint): what `planar_arm::__private::forward_solve` costs.
pub(crate) fn ldlt_solve_cost(n: usize, relative: usize) -> OpCount {
    let mut c = OpCount {
        div: n,
        mul: relative,
        add: n,
        ..OpCount::default()
    };
    for i in 0..n {
        for j in 0..i {
            // s_ij: j products subtracted; L_ij = s_ij / d_j.
            c.mul += j + 1;
            c.add += j;
        }
        // d_i: i products subtracted, then the floor's max; y_i: i products subtracted;
        // x_i: y_i / d_i, then n - 1 - i products subtracted.
        c.mul += i + i + 1 + (n - 1 - i);
        c.add += i + 1 + i + (n - 1 - i);
    }
    c
}

pub(crate) fn ldlt_solve(p: &mut Program, m: &[Vec<Id>], b: &[Id], floors: &[Id]) -> Vec<Id> {
    let n = m.len();
    let zero = p.constant(Rational::zero());
    let one = p.constant(Rational::from_integer(1.into()));
    // s[i][j] = L_ij d_j and l[i][j] = L_ij for j < i.
    let mut s = vec![vec![zero; n]; n];
    let mut l = vec![vec![zero; n]; n];
    let mut inv_d = vec![zero; n];
    for i in 0..n {
        for j in 0..i {
            let mut sij = m[i][j];
            for k in 0..j {
                let w = p.mul(l[i][k], s[j][k]);
                sij = p.sub(sij, w);
            }
            s[i][j] = sij;
            let lij = p.mul(sij, inv_d[j]);
            p.set_name(lij, format!("l{}", two(i, j)));
            l[i][j] = lij;
        }
        let mut di = m[i][i];
        for k in 0..i {
            let w = p.mul(l[i][k], s[i][k]);
            di = p.sub(di, w);
        }
        let di = p.max(di, floors[i]);
        p.set_name(di, format!("d{}", i + 1));
        let inv = p.div(one, di);
        p.set_name(inv, format!("inv_d{}", i + 1));
        inv_d[i] = inv;
    }
    // L y = b
    let mut y = Vec::with_capacity(n);
    for i in 0..n {
        let mut yi = b[i];
        for (k, &yk) in y.iter().enumerate() {
            let w = p.mul(l[i][k], yk);
            yi = p.sub(yi, w);
        }
        y.push(yi);
    }
    // D z = y, L^T x = z
    let mut x = vec![zero; n];
    for i in (0..n).rev() {
        let mut xi = p.mul(y[i], inv_d[i]);
        for k in i + 1..n {
            let w = p.mul(l[k][i], x[k]);
            xi = p.sub(xi, w);
        }
        x[i] = xi;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The count that `forward_dynamics`'s docs print for the run-time solve is the count of
    /// the program `ldlt_solve` builds on distinct inputs (nothing to share), plus one
    /// multiplication per run-time floor and one subtraction per joint for `tau - h`.
    #[test]
    fn solve_cost_counts_the_programs_operations() {
        for n in 1..=9 {
            for relative in [0, n] {
                let mut p = Program::new();
                let m: Vec<Vec<Id>> = (0..n)
                    .map(|i| {
                        (0..n)
                            .map(|j| p.input(Input::Q(i.max(j) * n + i.min(j))))
                            .collect()
                    })
                    .collect();
                let b: Vec<Id> = (0..n)
                    .map(|i| {
                        let (tau, h) = (p.input(Input::Tau(i)), p.input(Input::Qd(i)));
                        p.sub(tau, h)
                    })
                    .collect();
                let floors: Vec<Id> = (0..n)
                    .map(|i| {
                        if relative > 0 {
                            let ulp = p.constant(ulp());
                            p.mul(ulp, m[i][i])
                        } else {
                            p.constant(ulp())
                        }
                    })
                    .collect();
                let x = ldlt_solve(&mut p, &m, &b, &floors);
                assert_eq!(p.op_count(&x), ldlt_solve_cost(n, relative), "n = {n}");
            }
        }
    }
}
