//! Identification: the torques are linear in the standard parameters, `tau = Y(q, qd, qdd)
//! theta`, and only the base parameters (the identifiable combinations) can be found from
//! measured torques.
//!
//! The regressor is derived, not fitted: the arm's bodies are given symbolic standard
//! parameters (mass `m`, first moments `mx = m cx` and `my = m cy` in the link's frame, moment of
//! inertia about the joint `zz = Izz + m (cx^2 + cy^2)`), the joints symbolic armature `ia`
//! and viscous friction `fv`, and the equations of motion are derived over polynomials in
//! them ([`Dynamics::of_bodies`]). Each torque is then linear in the symbols, and the
//! coefficient of a symbol is its regressor column, exactly. The base parameters come from
//! exact rational elimination on those columns: no rank threshold.
//!
//! Coulomb friction `fc sign(qd_i)` is linear in `fc` too; its column, `sign(qd_i)` on row `i`,
//! is not an expression of the engine and is handled by the caller. Each is its own base
//! parameter.

use std::collections::BTreeMap;

use num_traits::{One, Zero};

use crate::expr::{Expr, Monomial};
use crate::mechanics::{ArmSpec, Body, Dynamics, LinkSpec, RateProducts};
use crate::poly::{Param, ParamMonomial, Poly};
use crate::ring::{Coefficient, Rational};
use crate::slp::Emit;
use crate::trig::{Angle, Trig};

/// What a standard parameter is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    /// Moment of inertia about the joint, `Izz + m (cx^2 + cy^2)`, kg m^2.
    Zz,
    /// First moment along the link, `m cx`, kg m.
    Mx,
    /// First moment across the link, `m cy`, kg m.
    My,
    /// Mass, kg.
    Mass,
    /// Armature (reflected rotor inertia), kg m^2.
    Armature,
    /// Viscous friction coefficient (`damping`), N m s/rad.
    Damping,
    /// Coulomb friction (`frictionloss`), N m. Its column, `sign(qd_i)` on row `i`, is not an
    /// expression of the engine: [`regressor`] leaves it out, the generated code adds it.
    Frictionloss,
}

/// A standard parameter: what it is and whose.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Standard {
    /// Its name: `zz1`, `mx1`, `my1`, `m1`, ... for link 1, `zzp`, `mxp`, `myp`, `mp` for the
    /// payload (in the last link's frame, from its joint), `ia1` and `fv1` for joint 1.
    pub name: String,
    /// What it is.
    pub kind: Kind,
    /// The link (0-based) for body parameters, `None` for the payload; the joint for
    /// `Armature` and `Damping`.
    pub link: Option<usize>,
}

/// The regressor of an arm: one column of exact torques per standard parameter.
#[derive(Clone, Debug)]
pub struct Regressor<C = Rational> {
    /// The standard parameters, in column order: per link `zz, mx, my`, then the payload's
    /// `zz, mx, my`, then the masses (links', payload's), then per joint the armature and the
    /// damping of the joints that have them.
    pub parameters: Vec<Standard>,
    /// `columns[k][i]`: torque `i` per unit of parameter `k`.
    pub columns: Vec<Vec<Expr<C>>>,
}

fn param(name: &str) -> Poly {
    Poly::param(Param::new(name))
}

/// The coefficient of `symbol` (which must occur at most linearly) in `c`, with the other
/// parameters kept: `Some` when `symbol` occurs.
fn linear_part(c: &Poly, symbol: &Param) -> Option<Poly> {
    let mut out = Poly::constant(Rational::zero());
    let mut found = false;
    for (m, r) in c.terms() {
        let powers = m.powers();
        if let Some(k) = powers.iter().position(|(p, _)| p == symbol) {
            found = true;
            let rest: Vec<(Param, u32)> = powers
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != k)
                .map(|(_, pe)| pe.clone())
                .collect();
            out = out + Poly::monomial(ParamMonomial::from_powers(rest), r.clone());
        }
    }
    found.then_some(out)
}

/// The standard parameters of `arm`, in column order (see [`Regressor::parameters`]), with
/// `fc` (Coulomb friction) of the joints that have it last; and the arm's geometry and bodies
/// with a symbol for each (named as the parameter), from which the energies and torques are
/// linear in them.
#[must_use]
pub fn symbolic(arm: &ArmSpec<Poly>) -> (Vec<Standard>, ArmSpec<Poly>, Vec<Body<Poly>>) {
    let n = arm.links.len();
    let mut parameters = Vec::new();
    let mut bodies = Vec::new();
    let mut push = |name: String, kind: Kind, link: Option<usize>| {
        let p = param(&name);
        parameters.push(Standard { name, kind, link });
        p
    };
    let mut masses = Vec::new();
    for i in 0..n {
        let zz = push(format!("zz{}", i + 1), Kind::Zz, Some(i));
        let mx = push(format!("mx{}", i + 1), Kind::Mx, Some(i));
        let my = push(format!("my{}", i + 1), Kind::My, Some(i));
        masses.push((format!("m{}", i + 1), Some(i)));
        bodies.push((i, zz, mx, my));
    }
    if arm.payload.is_some() {
        let zz = push("zzp".into(), Kind::Zz, None);
        let mx = push("mxp".into(), Kind::Mx, None);
        let my = push("myp".into(), Kind::My, None);
        masses.push(("mp".into(), None));
        bodies.push((n - 1, zz, mx, my));
    }
    let masses: Vec<Poly> = masses
        .into_iter()
        .map(|(name, link)| push(name, Kind::Mass, link))
        .collect();
    let bodies: Vec<Body<Poly>> = bodies
        .into_iter()
        .zip(masses)
        .map(|((link, zz, mx, my), mass)| Body {
            link,
            mass,
            first_moment: (mx, my),
            joint_inertia: zz,
        })
        .collect();
    let mut geometry = arm.clone();
    for (j, link) in geometry.links.iter_mut().enumerate() {
        let armature = if link.armature.is_zero() {
            Poly::constant(Rational::zero())
        } else {
            push(format!("ia{}", j + 1), Kind::Armature, Some(j))
        };
        *link = LinkSpec {
            armature,
            ..link.clone()
        };
    }
    for j in 0..n {
        if !arm.links[j].damping.is_zero() {
            push(format!("fv{}", j + 1), Kind::Damping, Some(j));
        }
    }
    for j in 0..n {
        if !arm.links[j].frictionloss.is_zero() {
            push(format!("fc{}", j + 1), Kind::Frictionloss, Some(j));
        }
    }
    (parameters, geometry, bodies)
}

/// Derives the regressor of `arm` (its lengths, gravity, and which joints have armature and
/// damping; its inertial values are what the regressor multiplies). Coulomb friction's columns
/// are left out (see [`Kind::Frictionloss`]).
#[must_use]
pub fn regressor(arm: &ArmSpec<Poly>) -> Regressor<Poly> {
    let n = arm.links.len();
    let (mut parameters, geometry, bodies) = symbolic(arm);
    parameters.retain(|s| s.kind != Kind::Frictionloss);
    let torques = Dynamics::of_bodies(&geometry, &bodies).torques();
    let columns = parameters
        .iter()
        .map(|s| {
            if s.kind == Kind::Damping {
                let j = s.link.unwrap_or(0);
                return (0..n)
                    .map(|i| {
                        if i == j {
                            Expr::var(crate::expr::Var::Qd(j))
                        } else {
                            Expr::zero()
                        }
                    })
                    .collect();
            }
            let symbol = Param::new(&s.name);
            torques
                .iter()
                .map(|t| {
                    let mut column = Expr::zero();
                    for (m, trig, c) in t.terms() {
                        if let Some(k) = linear_part(c, &symbol) {
                            column.add_assign(&Expr::term(k, trig.clone(), m.clone()));
                        }
                    }
                    column
                })
                .collect()
        })
        .collect();
    Regressor {
        parameters,
        columns,
    }
}

impl Regressor<Poly> {
    /// The columns with rational coefficients, `None` if one depends on a run-time parameter
    /// (a length or gravity).
    #[must_use]
    pub fn rational_columns(&self) -> Option<Vec<Vec<Expr<Rational>>>> {
        self.columns
            .iter()
            .map(|column| {
                column
                    .iter()
                    .map(|e| {
                        let mut out = Expr::zero();
                        for (m, t, c) in e.terms() {
                            out.add_assign(&Expr::term(c.as_rational()?, t.clone(), m.clone()));
                        }
                        Some(out)
                    })
                    .collect()
            })
            .collect()
    }
}

/// The standard parameters' values for the arm: `zz = I + m |c|^2`, `mx = m cx`, ...
#[must_use]
pub fn standard_values<C: Coefficient>(arm: &ArmSpec<C>, parameters: &[Standard]) -> Vec<C> {
    let bodies = crate::mechanics::standard_bodies(arm);
    let n = arm.links.len();
    parameters
        .iter()
        .map(|s| {
            let body = match s.link {
                Some(i) => bodies.get(i),
                None => bodies.get(n),
            };
            match (s.kind, body) {
                (Kind::Zz, Some(b)) => b.joint_inertia.clone(),
                (Kind::Mx, Some(b)) => b.first_moment.0.clone(),
                (Kind::My, Some(b)) => b.first_moment.1.clone(),
                (Kind::Mass, Some(b)) => b.mass.clone(),
                (Kind::Armature, _) => arm.links[s.link.unwrap_or(0)].armature.clone(),
                (Kind::Damping, _) => arm.links[s.link.unwrap_or(0)].damping.clone(),
                (Kind::Frictionloss, _) => arm.links[s.link.unwrap_or(0)].frictionloss.clone(),
                (_, None) => C::from_rational(Rational::zero()),
            }
        })
        .collect()
}

/// The base parameters: a minimal set of columns spanning the regressor, and each base
/// parameter as an exact combination of standard ones.
///
/// The coefficients are rationals for an arm whose lengths and gravity are numbers, and
/// polynomials in the run-time lengths otherwise (`zz1 + l1^2 m2`).
#[derive(Clone, Debug, PartialEq)]
pub struct BaseParameters<C = Rational> {
    /// The standard parameters whose columns are kept (indices into
    /// [`Regressor::parameters`]), in order.
    pub columns: Vec<usize>,
    /// For each base parameter, `(standard parameter, coefficient)` pairs: the base parameter
    /// is their sum. Its own parameter comes first with coefficient 1.
    pub grouping: Vec<Vec<(usize, C)>>,
}

impl<C: Emit> BaseParameters<C> {
    /// The base parameter `b` as a formula in the standard parameters' names:
    /// `zz1 + ia1 + 9/16 m2 + ...`, or with run-time lengths `zz1 + l1^2 m2`.
    #[must_use]
    pub fn formula(&self, b: usize, parameters: &[Standard]) -> String {
        let names: Vec<&str> = parameters.iter().map(|s| s.name.as_str()).collect();
        self.formula_named(b, &names)
    }

    /// [`formula`](Self::formula) with the standard parameters' names given.
    #[must_use]
    pub fn formula_named(&self, b: usize, names: &[&str]) -> String {
        let mut s = String::new();
        for (k, (p, c)) in self.grouping[b].iter().enumerate() {
            let name = names[*p];
            let (negative, mag) = c.sign_split();
            let sign = match (k, negative) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            };
            match mag.rational() {
                Some(r) if r.is_one() => s.push_str(&format!("{sign}{name}")),
                Some(r) => s.push_str(&format!("{sign}{r} {name}")),
                None => s.push_str(&format!("{sign}{mag} {name}")),
            }
        }
        s
    }
}

impl BaseParameters<Rational> {
    /// The same groupings over the polynomials.
    #[must_use]
    pub fn into_poly(self) -> BaseParameters<Poly> {
        BaseParameters {
            columns: self.columns,
            grouping: self
                .grouping
                .into_iter()
                .map(|g| g.into_iter().map(|(k, c)| (k, Poly::constant(c))).collect())
                .collect(),
        }
    }
}

type Key = (usize, Monomial, Trig);

/// A sparse vector over [`Key`]s.
type Sparse<C = Rational> = BTreeMap<Key, C>;

/// Exact elimination on the columns, in order: a column is a base column when it is not a
/// rational combination of the base columns before it. `None` if a column's coefficients are
/// not rational (run-time lengths or gravity: the combinations would be polynomials in them).
#[must_use]
pub fn base_parameters(reg: &Regressor<Poly>) -> Option<BaseParameters> {
    // Each column as a sparse vector over (row, monomial, atom).
    let mut vectors = Vec::new();
    for (k, column) in reg.columns.iter().enumerate() {
        let mut v = BTreeMap::new();
        for (i, e) in column.iter().enumerate() {
            for (m, t, c) in e.terms() {
                v.insert((i, m.clone(), t.clone()), c.as_rational()?);
            }
        }
        vectors.push((k, v));
    }
    eliminate(vectors)
}

/// A sparse vector over key indices, sorted.
type Indexed<C> = Vec<(u32, C)>;

/// `v - a w`, merged in order, zeros dropped.
fn axpy<C: Coefficient>(v: &Indexed<C>, a: &C, w: &Indexed<C>) -> Indexed<C> {
    let mut out = Vec::with_capacity(v.len() + w.len());
    let (mut i, mut j) = (0, 0);
    while i < v.len() || j < w.len() {
        match (v.get(i), w.get(j)) {
            (Some((ki, x)), Some((kj, y))) if ki == kj => {
                let z = x.clone() - a.clone() * y.clone();
                if !z.is_zero() {
                    out.push((*ki, z));
                }
                i += 1;
                j += 1;
            }
            (Some((ki, x)), Some((kj, _))) if ki < kj => {
                out.push((*ki, x.clone()));
                i += 1;
            }
            (Some((ki, x)), None) => {
                out.push((*ki, x.clone()));
                i += 1;
            }
            (_, Some((kj, y))) => {
                out.push((*kj, -(a.clone() * y.clone())));
                j += 1;
            }
            (None, None) => break,
        }
    }
    out
}

/// Exact elimination on `(column index, vector)` pairs, in order.
///
/// Over polynomials in run-time lengths the pivot of a vector is its first entry whose
/// coefficient is a nonzero number, so that every multiplier stays a polynomial; `None` if a
/// vector that does not vanish has no such entry (the groupings would be rational functions).
/// Over the rationals that is the first entry, as it always was.
fn eliminate<K: Ord + Clone, C: Emit>(
    vectors: Vec<(usize, BTreeMap<K, C>)>,
) -> Option<BaseParameters<C>> {
    // Keys as integers: the elimination compares them constantly, and the engine runs
    // unoptimised in a user's build.
    let mut keys: BTreeMap<K, u32> = BTreeMap::new();
    for (_, v) in &vectors {
        for key in v.keys() {
            let next = u32::try_from(keys.len()).unwrap_or(u32::MAX);
            keys.entry(key.clone()).or_insert(next);
        }
    }
    let vectors: Vec<(usize, Indexed<C>)> = vectors
        .into_iter()
        .map(|(k, v)| {
            let mut iv: Indexed<C> = v.into_iter().map(|(key, x)| (keys[&key], x)).collect();
            iv.sort_by_key(|e| e.0);
            (k, iv)
        })
        .collect();
    let one = || C::from_rational(Rational::one());
    // Echelon basis: (pivot, vector with 1 at the pivot, the vector as a combination of base
    // columns).
    let mut basis: Vec<(u32, Indexed<C>, BTreeMap<usize, C>)> = Vec::new();
    let mut base = Vec::new();
    let mut dependent: Vec<(usize, BTreeMap<usize, C>)> = Vec::new();
    for (k, v) in vectors {
        let mut v = v;
        let mut combo = BTreeMap::from([(k, one())]);
        for (pivot, b, bc) in &basis {
            let Ok(at) = v.binary_search_by_key(pivot, |e| e.0) else {
                continue;
            };
            let a = v[at].1.clone();
            v = axpy(&v, &a, b);
            for (j, x) in bc {
                let e = combo
                    .entry(*j)
                    .or_insert_with(|| C::from_rational(Rational::zero()));
                *e = e.clone() - a.clone() * x.clone();
                if e.is_zero() {
                    combo.remove(j);
                }
            }
        }
        if v.is_empty() {
            // 0 = Y_k + sum_j combo_j Y_j: Y_k = -sum_j combo_j Y_j.
            combo.remove(&k);
            dependent.push((k, combo));
            continue;
        }
        let (pivot, inv) = v.iter().find_map(|(key, x)| {
            let r = x.rational()?;
            (!Zero::is_zero(&r)).then(|| (*key, Rational::one() / r))
        })?;
        let v = v.into_iter().map(|(key, x)| (key, x.scale(&inv))).collect();
        let combo = combo.into_iter().map(|(j, x)| (j, x.scale(&inv))).collect();
        basis.push((pivot, v, combo));
        base.push(k);
    }
    // theta_b' = theta_b + sum over dependent j of beta_jb theta_j, Y_j = sum_b beta_jb Y_b.
    let mut grouping: Vec<Vec<(usize, C)>> = base.iter().map(|&b| vec![(b, one())]).collect();
    for (j, combo) in dependent {
        for (b, x) in combo {
            if let Some(slot) = base.iter().position(|&c| c == b) {
                grouping[slot].push((j, -x));
            }
        }
    }
    Some(BaseParameters {
        columns: base,
        grouping,
    })
}

/// The base parameters from the energies instead of the torques: the torques are Lagrange's
/// operator applied to `L = T - V`, which is linear in the parameters, and for `L` quadratic
/// in the rates plus a function of the angles the operator gives zero exactly when `L` is a
/// constant (its `qdd` part is M, so T's part vanishes, then dV/dq = 0). So the torque columns
/// satisfy exactly the rational relations that the energy columns satisfy up to constants:
/// elimination on `L`'s columns with constants dropped gives the same base parameters and
/// groupings as on the torques' ([`base_parameters`]; checked equal in the tests), without
/// deriving the torques. Damping and Coulomb friction (not in `L`) are each their own base
/// parameter, kept in order. `None` if a coefficient is not rational.
///
/// With run-time lengths the elimination runs over polynomials in them, and the groupings are
/// polynomials (`zz1 + l1^2 m2`), valid for every value of the lengths at which the same
/// columns stay independent (all but a few: a zero length, say). `None` if a multiplier would
/// not be a polynomial: with a run-time gravity (the first moments of link 1 enter the torques
/// only through it), and with run-time lengths and no gravity (the first moments then enter
/// only through `l_i cos(..)` terms).
#[must_use]
pub fn base_parameters_from_energies(
    arm: &ArmSpec<Poly>,
) -> Option<(Vec<Standard>, BaseParameters<Poly>)> {
    let (parameters, _, _) = symbolic(arm);
    // The geometry (lengths, joints, offsets, gravity) carrying unit rods: its energies with
    // one body at a time are the columns. Over the rationals when its values are numbers: the
    // common case, and several times faster than over polynomials.
    let geometry = ArmSpec {
        links: arm
            .links
            .iter()
            .map(|l| LinkSpec {
                length: l.length.clone(),
                joint: l.joint,
                offset: l.offset.clone(),
                reversed: l.reversed,
                ..LinkSpec::rod(
                    Poly::constant(Rational::one()),
                    Poly::constant(Rational::one()),
                )
            })
            .collect(),
        gravity: arm.gravity.clone(),
        payload: None,
    };
    let base = match geometry.as_rational() {
        Some(numbers) => energy_elimination(numbers, &parameters)?.into_poly(),
        None => energy_elimination(geometry, &parameters)?,
    };
    Some((parameters, base))
}

/// [`base_parameters_from_energies`] for an arm of this geometry (unit rods on its lengths,
/// joints, offsets and gravity).
fn energy_elimination<C: Emit>(
    geometry: ArmSpec<C>,
    parameters: &[Standard],
) -> Option<BaseParameters<C>> {
    let n = geometry.links.len();
    let num = |r: Rational| C::from_rational(r);
    // Each column of L = T - V directly: the energies of the geometry carrying one body whose
    // parameters are all zero but that one (or one rotor).
    let mut vectors = Vec::new();
    let mut friction = Vec::new();
    let mut rates = RateProducts::<C>::new();
    // A unit mass on link i: the energies of a point at joint i, the sum over the links
    // before it of S_a = 1/2 l_a^2 w_a^2 + sum_(b < a) l_a l_b cos(theta_a - theta_b) w_a w_b
    // plus g . (l_a cos(theta_a), l_a sin(theta_a)). Built as prefix sums: each unit-mass
    // energy from scratch cost the derive of a 30-link arm half a minute.
    let mut mass_columns: Vec<Expr<C>> = vec![Expr::zero()];
    let half = Rational::new(1.into(), 2.into());
    // With prismatic joints the lengths vary, and offsets and reversed joints change the
    // angles: each unit mass's energies come from the general route below instead.
    let revolute = geometry.all_revolute() && geometry.plain();
    for a in (0..n).filter(|_| revolute) {
        let la = &geometry.links[a].length;
        let mut step = rates
            .product(a, a)
            .scale_by(&(la.clone() * la.clone()).scale(&half));
        for b in 0..a {
            let lb = &geometry.links[b].length;
            let trig = Expr::cos(la.clone() * lb.clone(), Angle::range(b + 1, a + 1));
            step.add_assign(&rates.product(a, b).mul(&trig));
        }
        let (gx, gy) = &geometry.gravity;
        step.add_assign(&Expr::cos(gx.clone() * la.clone(), Angle::range(0, a + 1)));
        step.add_assign(&Expr::sin(gy.clone() * la.clone(), Angle::range(0, a + 1)));
        let next = mass_columns[a].add(&step);
        mass_columns.push(next);
    }
    let constant = |m: &Monomial, t: &Trig| m.degree() == 0 && *t == Trig::One;
    for (k, s) in parameters.iter().enumerate() {
        let link = s.link.unwrap_or(n - 1);
        if s.kind == Kind::Mass && revolute {
            let mut v: Sparse<C> = BTreeMap::new();
            for (m, t, c) in mass_columns[link].terms() {
                if !constant(m, t) {
                    v.insert((0, m.clone(), t.clone()), c.clone());
                }
            }
            vectors.push((k, v));
            continue;
        }
        let unit = |kind: Kind| {
            num(if s.kind == kind {
                Rational::one()
            } else {
                Rational::zero()
            })
        };
        let mut g = geometry.clone();
        let bodies = match s.kind {
            Kind::Damping | Kind::Frictionloss => {
                friction.push(k);
                continue;
            }
            Kind::Armature => {
                g.links[link].armature = num(Rational::one());
                Vec::new()
            }
            _ => vec![Body {
                link,
                mass: unit(Kind::Mass),
                first_moment: (unit(Kind::Mx), unit(Kind::My)),
                joint_inertia: unit(Kind::Zz),
            }],
        };
        let (kinetic, potential) = Dynamics::energies(&g, &bodies, &mut rates);
        let mut v: Sparse<C> = BTreeMap::new();
        for (m, t, c) in kinetic.sub(&potential).terms() {
            if !constant(m, t) {
                v.insert((0, m.clone(), t.clone()), c.clone());
            }
        }
        vectors.push((k, v));
    }
    let mut base = eliminate(vectors)?;
    for k in friction {
        base.columns.push(k);
        base.grouping.push(vec![(k, num(Rational::one()))]);
    }
    Some(base)
}

#[cfg(test)]
mod tests;
