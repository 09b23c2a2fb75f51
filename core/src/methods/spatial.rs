//! The programs `#[derive(SpatialArm)]` emits: for each method the cheaper of the product of
//! transformations (`programs::spatial`) and the expanded exact formulas
//! (`mechanics::spatial::frames`), by operation count.

use crate::algebra::expr::Expr;
use crate::algebra::poly::Poly;
use crate::mechanics::planar::JointKind;
use crate::mechanics::spatial::frames::SpatialKinematics;
use crate::mechanics::spatial::spec::SpatialArmSpec;
use crate::programs::method::Method;
use crate::programs::spatial as product;
use crate::slp::Program;

/// A spatial arm with its exact kinematics and the chosen programs.
#[derive(Clone, Debug)]
pub struct SpatialDerived {
    /// The exact kinematics, gravity and potential energy.
    pub kinematics: SpatialKinematics,
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

impl SpatialDerived {
    /// Derives the arm and chooses each method's program.
    #[must_use]
    pub fn new(arm: &SpatialArmSpec) -> Self {
        let k = SpatialKinematics::derive(arm);
        let n = arm.joints.len();
        let tip_pose = cheaper(product::tip_pose(arm), expanded(&frame_rows("", &k.tool)));
        let link_rows: Vec<(String, &Expr<Poly>)> = k
            .links
            .iter()
            .enumerate()
            .flat_map(|(i, f)| frame_rows(&format!("l{}", i + 1), f))
            .collect();
        let link_poses = cheaper(product::link_poses(arm), expanded(&link_rows));
        // The expanded Jacobian: the tool position's derivatives, and each hinge's axis.
        let derivatives: Vec<Vec<Expr<Poly>>> = (0..3)
            .map(|r| (0..n).map(|i| k.tool.p[r].diff_q(i)).collect())
            .collect();
        let zero = Expr::zero();
        let mut j_rows = Vec::with_capacity(6 * n);
        for r in 0..6 {
            for (i, joint) in arm.joints.iter().enumerate() {
                let e = if let Some(row) = derivatives.get(r) {
                    &row[i]
                } else if joint.kind == JointKind::Revolute {
                    &k.axes[i].1[r - 3]
                } else {
                    &zero
                };
                j_rows.push((format!("j{}{}", r + 1, i + 1), e));
            }
        }
        let jacobian = cheaper(product::jacobian(arm), expanded(&j_rows));
        let (g_product, v_product) = product::gravity(arm);
        let g_rows: Vec<(String, &Expr<Poly>)> = k
            .gravity
            .iter()
            .enumerate()
            .map(|(i, e)| (format!("g{}", i + 1), e))
            .collect();
        let gravity = cheaper(g_product, expanded(&g_rows));
        let potential_energy = cheaper(
            v_product,
            expanded(&[("v".to_string(), &k.potential_energy)]),
        );
        Self {
            kinematics: k,
            tip_pose,
            link_poses,
            jacobian,
            gravity,
            potential_energy,
        }
    }
}
