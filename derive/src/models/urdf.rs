//! URDF, as ROS and Pinocchio read it: links and their `<inertial>`, `revolute`, `continuous`,
//! `prismatic` and `fixed` joints with `origin`, `axis` (default `1 0 0`), `limit` and
//! `dynamics`. Visual and collision elements, transmissions and `gazebo` tags do not change the
//! dynamics and are not read.

use planar_arm_core::mechanics::spatial::FixedAngle;
use planar_arm_core::ring::int;
use planar_arm_core::JointKind;
use roxmltree::Node;

use super::frame::{Inertial, Pose};
use super::tree::{Body, FileError, Joint, Motion, Tree};
use super::xml::{child, children, Xml};

fn angles(v: [planar_arm_core::ring::Rational; 3]) -> [FixedAngle; 3] {
    v.map(|r| FixedAngle {
        radians: r,
        pi_multiple: int(0),
    })
}

/// `<origin xyz=".." rpy=".."/>` inside `node`, identity where absent.
fn origin(xml: &Xml<'_>, node: Node<'_, '_>) -> Result<Pose, FileError> {
    let Some(o) = child(node, "origin") else {
        return Ok(Pose::identity());
    };
    let mut pose = Pose::identity();
    if let Some(xyz) = xml.triple(o, "xyz")? {
        pose.xyz = xyz;
    }
    if let Some(rpy) = xml.triple(o, "rpy")? {
        pose.rpy = angles(rpy);
    }
    Ok(pose)
}

/// A link's `<inertial>` in the link's frame (the tensor turned by the inertial's `rpy`).
fn inertial(xml: &Xml<'_>, link: Node<'_, '_>) -> Result<Option<Inertial>, FileError> {
    let Some(node) = child(link, "inertial") else {
        return Ok(None);
    };
    let mass = match child(node, "mass") {
        Some(m) => xml.number(m, "value")?,
        None => None,
    }
    .unwrap_or_else(|| int(0));
    let mut tensor: [planar_arm_core::ring::Rational; 6] = Default::default();
    if let Some(i) = child(node, "inertia") {
        for (k, key) in ["ixx", "iyy", "izz", "ixy", "ixz", "iyz"]
            .iter()
            .enumerate()
        {
            tensor[k] = xml.number(i, key)?.unwrap_or_else(|| int(0));
        }
    }
    let body = Inertial {
        mass,
        com: Default::default(),
        inertia: tensor,
    };
    if body.is_negative() {
        return Err(xml.error(
            node,
            format!(
                "link `{}`: a negative mass or moment of inertia",
                link.attribute("name").unwrap_or("?")
            ),
        ));
    }
    // The tensor is about the centre of mass in the inertial frame's axes: turn it into the
    // link's, then place its centre.
    let o = origin(xml, node)?;
    let turned = body.moved(&Pose {
        xyz: Default::default(),
        rpy: o.rpy,
    });
    Ok(Some(Inertial {
        com: o.xyz,
        ..turned
    }))
}

fn joint_motion(xml: &Xml<'_>, j: Node<'_, '_>, name: &str) -> Result<Motion, FileError> {
    let kind = match j.attribute("type") {
        Some("revolute" | "continuous") => JointKind::Revolute,
        Some("prismatic") => JointKind::Prismatic,
        Some("fixed") => return Ok(Motion::Fixed),
        Some(other) => {
            return Ok(Motion::Unsupported(format!(
            "a `{other}` joint `{name}`, which a serial arm of hinges and slides cannot represent"
        )))
        }
        None => return Err(xml.error(j, format!("joint `{name}` has no `type`"))),
    };
    if child(j, "mimic").is_some() {
        return Ok(Motion::Unsupported(format!(
            "joint `{name}`, which mimics another: a coupling a serial arm of independent \
             joints cannot represent"
        )));
    }
    let axis = match child(j, "axis") {
        Some(a) => xml.triple(a, "xyz")?,
        None => None,
    }
    .unwrap_or_else(|| [int(1), int(0), int(0)]);
    if axis.iter().all(num_traits::Zero::is_zero) {
        return Err(xml.error(j, format!("joint `{name}` has a zero axis")));
    }
    let range = match (child(j, "limit"), j.attribute("type")) {
        (Some(l), Some("revolute" | "prismatic")) => {
            match (xml.number(l, "lower")?, xml.number(l, "upper")?) {
                (Some(lo), Some(hi)) if lo < hi => Some((lo, hi)),
                _ => None,
            }
        }
        _ => None,
    };
    let (mut damping, mut frictionloss) = (int(0), int(0));
    if let Some(d) = child(j, "dynamics") {
        damping = xml.number(d, "damping")?.unwrap_or_else(|| int(0));
        frictionloss = xml.number(d, "friction")?.unwrap_or_else(|| int(0));
        if num_traits::Signed::is_negative(&damping)
            || num_traits::Signed::is_negative(&frictionloss)
        {
            return Err(xml.error(
                d,
                format!("joint `{name}`: negative damping or friction would feed energy in"),
            ));
        }
    }
    Ok(Motion::Joint(Joint {
        name: name.to_string(),
        kind,
        axis,
        range,
        armature: int(0),
        damping,
        frictionloss,
        stiffness: int(0),
        springref: int(0),
    }))
}

/// The tree of a URDF file.
pub fn read(xml: &Xml<'_>) -> Result<Tree, FileError> {
    let robot = xml.doc.root_element();
    if !robot.has_tag_name("robot") {
        return Err(xml.error(robot, "a URDF file's root element is <robot>"));
    }
    let links: Vec<Node<'_, '_>> = children(robot, "link").collect();
    let joints: Vec<Node<'_, '_>> = children(robot, "joint").collect();
    let name = |n: Node<'_, '_>| -> Result<String, FileError> {
        n.attribute("name")
            .map(str::to_string)
            .ok_or_else(|| xml.error(n, format!("<{}> without a `name`", n.tag_name().name())))
    };
    // Each joint as (parent link, child link, node).
    let mut edges = Vec::new();
    for j in &joints {
        let end = |tag: &'static str| {
            child(*j, tag)
                .and_then(|n| n.attribute("link"))
                .ok_or_else(|| xml.error(*j, format!("joint without <{tag} link=\"..\"/>")))
        };
        edges.push((end("parent")?, end("child")?, *j));
    }
    for (_, c, j) in &edges {
        if !links.iter().any(|l| l.attribute("name") == Some(c)) {
            return Err(xml.error(*j, format!("the child link `{c}` is not defined")));
        }
    }
    let roots: Vec<Node<'_, '_>> = links
        .iter()
        .copied()
        .filter(|l| !edges.iter().any(|(_, c, _)| l.attribute("name") == Some(c)))
        .collect();
    let root = match roots.as_slice() {
        [root] => *root,
        [] => return Err(xml.error(robot, "no root link: every link is some joint's child")),
        [_, second, ..] => {
            return Err(xml.error(
                *second,
                format!(
                    "a second root link `{}`: a URDF is one tree",
                    name(*second)?
                ),
            ))
        }
    };
    let mut tree = Tree::default();
    tree.bodies.push(Body {
        name: name(root)?,
        parent: None,
        origin: Pose::identity(),
        motion: Motion::Fixed,
        inertial: inertial(xml, root)?,
        loc: xml.loc(root),
    });
    // Breadth first from the root, so that parents come before children.
    let mut k = 0;
    while k < tree.bodies.len() {
        let parent = tree.bodies[k].name.clone();
        for (p, c, j) in &edges {
            if *p != parent {
                continue;
            }
            if tree.find(c).is_some() {
                return Err(xml.error(
                    *j,
                    format!("link `{c}` is reached twice: a URDF is one tree"),
                ));
            }
            let link = links
                .iter()
                .copied()
                .find(|l| l.attribute("name") == Some(c))
                .ok_or_else(|| xml.error(*j, format!("the child link `{c}` is not defined")))?;
            let jname = name(*j)?;
            tree.bodies.push(Body {
                name: (*c).to_string(),
                parent: Some(k),
                origin: origin(xml, *j)?,
                motion: joint_motion(xml, *j, &jname)?,
                inertial: inertial(xml, link)?,
                loc: xml.loc(*j),
            });
        }
        k += 1;
    }
    Ok(tree)
}
