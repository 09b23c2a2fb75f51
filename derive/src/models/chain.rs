//! The serial chain a derive takes from a tree: the bodies from the base to the tip, each
//! moving link carrying every body welded to it, as Pinocchio's `buildReducedModel` does.
//!
//! Bodies hanging off the chain (a gripper's fingers, a Panda's hand beyond `tip`) are merged
//! rigidly into the chain body they hang from, their joints locked at zero; bodies that do not
//! move with any joint of the chain (the base and what hangs from it) are dropped.

use super::frame::{Inertial, Pose};
use super::tree::{FileError, Joint, Motion, Tree};

/// One joint of the chain and the link it moves.
#[derive(Debug)]
pub struct ChainJoint {
    /// The joint's frame in the previous link's frame (or the base's) at zero.
    pub origin: Pose,
    pub joint: Joint,
    /// The link's mass properties in the joint's frame, welded bodies included.
    pub body: Inertial,
}

/// A chain and its tool frame.
#[derive(Debug)]
pub struct Chain {
    pub joints: Vec<ChainJoint>,
    /// The tip body's frame in the last link's frame.
    pub tool: Pose,
    /// The joints locked at zero because they hang off the chain.
    pub locked: Vec<String>,
}

/// The names of the bodies nearest to `name`, for "did you mean".
fn candidates(tree: &Tree) -> String {
    let names: Vec<&str> = tree.bodies.iter().map(|b| b.name.as_str()).collect();
    let shown: Vec<String> = names.iter().take(12).map(|n| format!("`{n}`")).collect();
    let more = if names.len() > 12 { ", ..." } else { "" };
    format!("{}{more}", shown.join(", "))
}

fn find(tree: &Tree, file: &str, what: &str, name: &str) -> Result<usize, FileError> {
    tree.find(name).ok_or_else(|| {
        let near = crate::attr::nearest(
            name,
            &tree
                .bodies
                .iter()
                .map(|b| b.name.as_str())
                .collect::<Vec<_>>(),
        )
        .map_or_else(String::new, |n| format!("did you mean `{n}`? "));
        FileError(format!(
            "{file}: no body or link named `{name}` for `{what}`; {near}the file has {}",
            candidates(tree)
        ))
    })
}

/// The path of bodies from `base` to the tip, base first.
fn path(tree: &Tree, file: &str, base: usize, tip: Option<usize>) -> Result<Vec<usize>, FileError> {
    if let Some(tip) = tip {
        let mut path = vec![tip];
        let mut b = tip;
        while b != base {
            let Some(p) = tree.bodies[b].parent else {
                return Err(FileError(format!(
                    "{file}: `{}` does not hang from `{}`; give a `tip` below the `base`",
                    tree.bodies[tip].name, tree.bodies[base].name
                )));
            };
            path.push(p);
            b = p;
        }
        path.reverse();
        return Ok(path);
    }
    let mut path = vec![base];
    let mut b = base;
    loop {
        let children: Vec<usize> = tree.children(b).collect();
        let moving: Vec<usize> = children
            .iter()
            .copied()
            .filter(|&c| tree.moves(c))
            .collect();
        b = match (moving.as_slice(), children.as_slice()) {
            ([one], _) | ([], [one]) => *one,
            ([], _) => return Ok(path),
            (many, _) => {
                let names: Vec<String> = many
                    .iter()
                    .map(|&c| format!("`{}`", tree.bodies[c].name))
                    .collect();
                return Err(FileError(format!(
                    "{file}: the chain branches at `{}` into {}; say which branch with \
                     `tip = \"...\"` (a body or link name)",
                    tree.bodies[b].name,
                    names.join(" and ")
                )));
            }
        };
        path.push(b);
    }
}

/// Everything in `b`'s subtree, welded at zero, seen from the frame in which `pose` (`b`'s
/// frame) is given; the joints it locks are added to `locked`.
fn welded(tree: &Tree, b: usize, pose: &Pose, locked: &mut Vec<String>) -> Inertial {
    let body = &tree.bodies[b];
    match &body.motion {
        Motion::Joint(j) => locked.push(j.name.clone()),
        Motion::Unsupported(_) => locked.push(body.name.clone()),
        Motion::Fixed => {}
    }
    let mut sum = body
        .inertial
        .as_ref()
        .map_or_else(Inertial::default, |i| i.moved(pose));
    for c in tree.children(b) {
        let at = pose.then(&tree.bodies[c].origin);
        sum = sum.merged(&welded(tree, c, &at, locked));
    }
    sum
}

/// The chain from `base` (default: the root) to `tip` (default: the only branch that moves).
pub fn chain(
    tree: &Tree,
    file: &str,
    base: Option<&str>,
    tip: Option<&str>,
) -> Result<Chain, FileError> {
    let base = base.map_or(Ok(0), |n| find(tree, file, "base", n))?;
    let tip = tip.map(|n| find(tree, file, "tip", n)).transpose()?;
    let path = path(tree, file, base, tip)?;
    let mut joints: Vec<ChainJoint> = Vec::new();
    let mut locked = Vec::new();
    // The current body's frame in the current link's frame (or the base's).
    let mut pending = Pose::identity();
    for (k, &b) in path.iter().enumerate() {
        let body = &tree.bodies[b];
        if k > 0 {
            match &body.motion {
                Motion::Fixed => pending = pending.then(&body.origin),
                Motion::Joint(j) => {
                    joints.push(ChainJoint {
                        origin: pending.then(&body.origin),
                        joint: j.clone(),
                        body: Inertial::default(),
                    });
                    pending = Pose::identity();
                }
                Motion::Unsupported(what) => {
                    return Err(FileError::at(
                        &body.loc,
                        format!("`{}` hangs on the chain by {what}", body.name),
                    ))
                }
            }
        }
        // Bodies before the first joint do not move: dropped.
        let Some(link) = joints.last_mut() else {
            continue;
        };
        if let Some(i) = &body.inertial {
            link.body = link.body.merged(&i.moved(&pending));
        }
        let next = path.get(k + 1).copied();
        for c in tree.children(b).filter(|&c| Some(c) != next) {
            let at = pending.then(&tree.bodies[c].origin);
            link.body = link.body.merged(&welded(tree, c, &at, &mut locked));
        }
    }
    if joints.is_empty() {
        return Err(FileError(format!(
            "{file}: no hinge or slide between `{}` and `{}`; nothing would move",
            tree.bodies[base].name,
            tree.bodies[*path.last().unwrap_or(&base)].name
        )));
    }
    for c in &tree.couplings {
        if let Some(j) = joints.iter().find(|j| c.joints.contains(&j.joint.name)) {
            return Err(FileError::at(
                &c.loc,
                format!(
                    "{} couples the chain's joint `{}` to others; a serial arm of independent \
                     joints cannot represent it",
                    c.what, j.joint.name
                ),
            ));
        }
    }
    Ok(Chain {
        joints,
        tool: pending,
        locked,
    })
}
