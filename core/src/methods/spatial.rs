//! The programs `#[derive(SpatialArm)]` emits: for each method the cheaper of the product of
//! transformations (`programs::spatial`) and the expanded exact formulas
//! (`mechanics::spatial::frames`), by operation count.

use crate::algebra::expr::Expr;
use crate::algebra::poly::Poly;
use crate::mechanics::planar::JointKind;
use crate::mechanics::spatial::frames::{SpatialKinematics, EXPANSION_BUDGET};
use crate::mechanics::spatial::lagrangian::{
    expand_dynamics, SpatialDynamicsExpansion, DYNAMICS_BUDGET,
};
use crate::mechanics::spatial::spec::SpatialArmSpec;
use crate::programs::method::Method;
use crate::programs::spatial as product;
use crate::programs::spatial_composite as composite;
use crate::programs::spatial_newton_euler as newton_euler;
use crate::programs::unrolled::Terms;
use crate::slp::Program;

/// A spatial arm with its exact kinematics and the chosen programs.
#[derive(Clone, Debug)]
pub struct SpatialDerived {
    /// The exact kinematics, gravity and potential energy, multiplied out; `None` when they
    /// would exceed [`EXPANSION_BUDGET`] terms.
    pub kinematics: Option<SpatialKinematics>,
    /// The tool pose: rotation row-major, then position.
    pub tip_pose: Method,
    /// Every link's pose, twelve outputs each.
    pub link_poses: Method,
    /// The geometric Jacobian, row-major.
    pub jacobian: Method,
    /// The gravity torques.
    pub gravity: Method,
    /// The potential energy.
    pub potential_energy: Method,
    /// The joint forces `M qdd + c + g + f`, by the unrolled Newton-Euler recursion.
    pub inverse_dynamics: Method,
    /// The mass matrix, row-major, by the unrolled composite-rigid-body algorithm.
    pub mass_matrix: Method,
    /// The velocity-product forces `c`.
    pub coriolis: Method,
    /// The bias `c + g + f`.
    pub bias: Method,
    /// The joint friction `f`.
    pub friction: Method,
    /// The mass matrix (row-major) and the bias in one program.
    pub mass_matrix_and_bias: Method,
    /// The Coriolis matrix (row-major), from Christoffel symbols of M.
    pub coriolis_matrix: Method,
    /// `(dtau/dq, dtau/dqd)`, row-major each, where the program stays small.
    pub inverse_dynamics_derivatives: Option<Method>,
    /// `(-M^-1 dtau/dq, -M^-1 dtau/dqd)` in reverse mode for a run-time `M^-1`, row-major each,
    /// where the inverse dynamics' derivatives are emitted.
    pub forward_dynamics_adjoint: Option<Box<crate::packed::Packed>>,
    /// M and c multiplied out from the Lagrangian, for `EXACT` and the docs; `None` where the
    /// kinematics is not expanded or they would exceed [`DYNAMICS_BUDGET`].
    pub dynamics: Option<SpatialDynamicsExpansion>,
}

impl SpatialDerived {
    /// The dynamics' programs, which do not depend on the form the kinematics take; M and c
    /// multiplied out within `budget` where the kinematics is.
    fn with_dynamics(
        arm: &SpatialArmSpec,
        kinematics: Option<SpatialKinematics>,
        [tip_pose, link_poses, jacobian, gravity, potential_energy]: [Method; 5],
        budget: usize,
    ) -> Self {
        let dynamics = kinematics
            .as_ref()
            .and_then(|_| expand_dynamics(arm, budget));
        let (inverse_dynamics_derivatives, adjoint) =
            newton_euler::inverse_dynamics_derivatives(arm);
        let forward_dynamics_adjoint = adjoint.map(Box::new);
        Self {
            kinematics,
            dynamics,
            tip_pose,
            link_poses,
            jacobian,
            gravity,
            potential_energy,
            inverse_dynamics: newton_euler::inverse_dynamics(arm, Terms::ALL, true),
            mass_matrix: composite::mass_matrix(arm),
            coriolis: newton_euler::inverse_dynamics(arm, Terms::CORIOLIS, false),
            bias: newton_euler::inverse_dynamics(arm, Terms::BIAS, true),
            friction: newton_euler::friction_method(arm),
            mass_matrix_and_bias: composite::mass_matrix_and_bias(arm),
            coriolis_matrix: composite::coriolis_matrix(arm),
            inverse_dynamics_derivatives,
            forward_dynamics_adjoint,
        }
    }
}

/// The program that evaluates `rows` term by term.
fn expanded(rows: &[(String, &Expr<Poly>)]) -> Method {
    let mut p = Program::new();
    let outputs = rows
        .iter()
        .map(|(name, e)| (name.clone(), p.expr(e)))
        .collect();
    Method::new(p, outputs)
}

/// The cheaper of two programs of the same outputs; the first on a tie.
fn cheaper(a: Method, b: Method) -> Method {
    let cost = |m: &Method| {
        let c = m.op_count();
        c.mul + c.add + crate::slp::DIV_LATENCY * c.div
    };
    if cost(&b) < cost(&a) {
        b
    } else {
        a
    }
}

fn frame_rows<'a>(
    prefix: &str,
    f: &'a crate::mechanics::spatial::frames::Frame,
) -> Vec<(String, &'a Expr<Poly>)> {
    let mut rows = Vec::new();
    for i in 0..3 {
        for j in 0..3 {
            rows.push((format!("{prefix}r{}{}", i + 1, j + 1), &f.r[i][j]));
        }
    }
    for i in 0..3 {
        rows.push((format!("{prefix}p{}", i + 1), &f.p[i]));
    }
    rows
}

/// Which program each method gets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpatialForm {
    /// The product of the joints' transformations, evaluated link by link.
    Product,
    /// The expanded exact formulas, term by term.
    Expanded,
    /// The cheaper of the two by operation count, method by method (what the derive emits).
    Cheaper,
}

impl SpatialForm {
    fn pick(self, product: Method, expanded: Method) -> Method {
        match self {
            Self::Product => product,
            Self::Expanded => expanded,
            Self::Cheaper => cheaper(product, expanded),
        }
    }
}

impl SpatialDerived {
    /// Derives the arm and chooses each method's program: what the derive emits.
    #[must_use]
    pub fn new(arm: &SpatialArmSpec) -> Self {
        Self::in_form(arm, SpatialForm::Cheaper)
    }

    /// As [`new`](Self::new), with M and c multiplied out whatever their size (the arm's
    /// `#[arm(exact_dynamics)]`), where the kinematics is.
    #[must_use]
    pub fn with_exact_dynamics(arm: &SpatialArmSpec) -> Self {
        Self::within(arm, SpatialForm::Cheaper, usize::MAX)
    }

    /// Derives the arm with every method in `form` (tests check both forms against the
    /// reference, whichever the derive would choose). An arm whose expansion exceeds
    /// [`EXPANSION_BUDGET`] gets the product form whatever `form` asks.
    #[must_use]
    pub fn in_form(arm: &SpatialArmSpec, form: SpatialForm) -> Self {
        Self::within(arm, form, DYNAMICS_BUDGET)
    }

    /// [`in_form`](Self::in_form) with M and c multiplied out within `budget`.
    fn within(arm: &SpatialArmSpec, form: SpatialForm, budget: usize) -> Self {
        let (g_product, v_product) = product::gravity(arm);
        let Some(k) = SpatialKinematics::derive_within(arm, EXPANSION_BUDGET) else {
            let kinematics = [
                product::tip_pose(arm),
                product::link_poses(arm),
                product::jacobian(arm),
                g_product,
                v_product,
            ];
            return Self::with_dynamics(arm, None, kinematics, budget);
        };
        let tip_pose = form.pick(product::tip_pose(arm), expanded(&frame_rows("", &k.tool)));
        let link_rows: Vec<(String, &Expr<Poly>)> = k
            .links
            .iter()
            .enumerate()
            .flat_map(|(i, f)| frame_rows(&format!("l{}", i + 1), f))
            .collect();
        let link_poses = form.pick(product::link_poses(arm), expanded(&link_rows));
        let jacobian = form.pick(product::jacobian(arm), expanded_jacobian(arm, &k));
        let g_rows: Vec<(String, &Expr<Poly>)> = k
            .gravity
            .iter()
            .enumerate()
            .map(|(i, e)| (format!("g{}", i + 1), e))
            .collect();
        let gravity = form.pick(g_product, expanded(&g_rows));
        let potential_energy = form.pick(
            v_product,
            expanded(&[("v".to_string(), &k.potential_energy)]),
        );
        Self::with_dynamics(
            arm,
            Some(k),
            [tip_pose, link_poses, jacobian, gravity, potential_energy],
            budget,
        )
    }
}

/// The expanded Jacobian: the tool position's derivatives, and each hinge's axis.
fn expanded_jacobian(arm: &SpatialArmSpec, k: &SpatialKinematics) -> Method {
    let n = arm.joints.len();
    let derivatives: Vec<Vec<Expr<Poly>>> = (0..3)
        .map(|r| (0..n).map(|i| k.tool.p[r].diff_q(i)).collect())
        .collect();
    let zero = Expr::zero();
    let mut rows = Vec::with_capacity(6 * n);
    for r in 0..6 {
        for (i, joint) in arm.joints.iter().enumerate() {
            let e = if let Some(row) = derivatives.get(r) {
                &row[i]
            } else if joint.kind == JointKind::Revolute {
                &k.axes[i].1[r - 3]
            } else {
                &zero
            };
            rows.push((format!("j{}{}", r + 1, i + 1), e));
        }
    }
    expanded(&rows)
}
