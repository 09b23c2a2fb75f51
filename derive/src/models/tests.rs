//! Bad model files: each error names the file, the line and what is wrong.

use super::{import, Format};
use planar_arm_core::ring::{int, ratio, Rational};
use planar_arm_core::Poly;

/// A file written for one test, by absolute path (which `import` takes as it is).
fn file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("planar_arm_models_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

fn error(format: Format, path: &str, base: Option<&str>, tip: Option<&str>) -> String {
    match import(format, path, base, tip) {
        Ok(i) => panic!("{path} imported: {:?}", i.names),
        Err(e) => e.0,
    }
}

#[test]
fn a_missing_file_says_where_it_was_looked_for() {
    let e = error(Format::Urdf, "models/none.urdf", None, None);
    assert!(e.starts_with("cannot read `models/none.urdf`"), "{e}");
    assert!(e.contains("relative to the crate's Cargo.toml"), "{e}");
}

#[test]
fn malformed_xml_names_the_line() {
    let p = file(
        "bad.urdf",
        "<robot name=\"r\">\n  <link name=\"a\">\n</robot>\n",
    );
    let e = error(Format::Urdf, &p, None, None);
    assert!(e.starts_with(&format!("{p}:3:")), "{e}");
    assert!(e.contains("malformed XML"), "{e}");
}

#[test]
fn an_unknown_tip_suggests_the_nearest_name() {
    let e = error(Format::Urdf, "../models/ur5.urdf", None, Some("tool"));
    assert!(e.contains("no body or link named `tool` for `tip`"), "{e}");
    assert!(e.contains("did you mean `tool0`?"), "{e}");
}

#[test]
fn a_branching_chain_needs_a_tip() {
    let e = error(Format::Urdf, "../models/panda.urdf", None, None);
    assert!(
        e.contains(
            "the chain branches at `panda_hand` into `panda_leftfinger` and `panda_rightfinger`"
        ),
        "{e}"
    );
    // Through a finger, its mimic joint is a coupling the chain cannot hold.
    let e = error(
        Format::Urdf,
        "../models/panda.urdf",
        None,
        Some("panda_rightfinger"),
    );
    assert!(e.contains("mimics another"), "{e}");
    assert!(e.starts_with("../models/panda.urdf:"), "{e}");
}

#[test]
fn a_free_joint_on_the_chain_is_refused_with_its_line() {
    let p = file(
        "free.xml",
        "<mujoco>\n<worldbody>\n<body name=\"ball\">\n  <freejoint/>\n  \
         <geom size=\"0.1\"/>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    let e = error(Format::Mjcf, &p, None, None);
    assert!(e.starts_with(&format!("{p}:4:3:")), "{e}");
    assert!(e.contains("hangs on the chain by a free joint"), "{e}");
}

#[test]
fn a_tendon_coupling_chain_joints_is_refused() {
    let p = file(
        "tendon.xml",
        "<mujoco>\n<worldbody>\n<body name=\"a\"><joint name=\"j1\"/><geom size=\"0.1\"/>\n\
         <body name=\"b\"><joint name=\"j2\"/><geom size=\"0.1\"/></body></body>\n</worldbody>\n\
         <tendon>\n  <fixed name=\"t\"><joint joint=\"j1\" coef=\"1\"/><joint joint=\"j2\" coef=\"-1\"/></fixed>\n</tendon>\n</mujoco>\n",
    );
    let e = error(Format::Mjcf, &p, None, None);
    assert!(e.starts_with(&format!("{p}:7:3:")), "{e}");
    assert!(e.contains("couples the chain's joint `j1`"), "{e}");
}

#[test]
fn a_body_whose_inertia_needs_a_mesh_says_so() {
    let p = file(
        "mesh.xml",
        "<mujoco>\n<worldbody>\n<body name=\"a\"><joint/>\n<geom type=\"mesh\" mesh=\"m\"/>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    let e = error(Format::Mjcf, &p, None, None);
    assert!(e.starts_with(&format!("{p}:4:1:")), "{e}");
    assert!(
        e.contains("`mesh` geom's mass properties need its shape"),
        "{e}"
    );
}

#[test]
fn nothing_that_moves_is_an_error() {
    let p = file("still.urdf", "<robot name=\"r\"><link name=\"a\"/></robot>");
    let e = error(Format::Urdf, &p, None, None);
    assert!(e.contains("no hinge or slide between `a` and `a`"), "{e}");
}

#[test]
fn a_hinge_about_its_anchor_with_ref_reads_qpos() {
    // A pendulum whose hinge sits 0.5 above the body origin, ref 90 degrees: the link frame is
    // at the anchor and turned back by ref, so q = qpos.
    let p = file(
        "anchor.xml",
        "<mujoco>\n<worldbody>\n<body name=\"p\" pos=\"0 0 1\">\n<joint name=\"h\" pos=\"0 0 0.5\" \
         axis=\"0 1 0\" ref=\"90\"/>\n<geom type=\"sphere\" size=\"0.1\" mass=\"2\"/>\n</body>\n\
         </worldbody>\n</mujoco>\n",
    );
    let i = import(Format::Mjcf, &p, None, None).unwrap();
    assert_eq!(i.names, ["h"]);
    let planar_arm_core::mechanics::spatial::SpatialGeometry::Urdf { xyz, rpy, .. } =
        &i.joints[0].geometry
    else {
        panic!("not an origin joint");
    };
    use planar_arm_core::ring::{int, ratio};
    use planar_arm_core::Poly;
    assert_eq!(
        xyz,
        &[
            Poly::default(),
            Poly::default(),
            Poly::constant(ratio(3, 2))
        ]
    );
    assert_eq!(
        rpy[1],
        planar_arm_core::mechanics::spatial::FixedAngle::pi(ratio(-1, 2))
    );
    // The ball 0.5 below the anchor in the link's own (turned) frame: it hangs there at
    // q = ref, where the turn and the fold cancel.
    assert_eq!(
        i.joints[0].com,
        [
            Poly::default(),
            Poly::default(),
            Poly::constant(ratio(-1, 2))
        ]
    );
    assert_eq!(i.joints[0].mass, Poly::constant(int(2)));
}

#[test]
fn frames_and_orientations_compose_as_mujoco_places_bodies() {
    // A <frame> turned 90 degrees about z holding a body shifted along its x: the body sits
    // on the world's y axis, turned with the frame; its xyaxes turn it back.
    let p = file(
        "frame.xml",
        "<mujoco>\n<worldbody>\n<frame pos=\"1 0 0\" euler=\"0 0 90\">\n\
         <body name=\"b\" pos=\"2 0 0\" xyaxes=\"0 -1 0 1 0 0\">\n<joint name=\"j\" axis=\"1 0 0\"/>\n\
         <geom type=\"sphere\" size=\"0.1\" mass=\"1\"/>\n</body>\n</frame>\n</worldbody>\n</mujoco>\n",
    );
    let i = import(Format::Mjcf, &p, None, None).unwrap();
    let planar_arm_core::mechanics::spatial::SpatialGeometry::Urdf { xyz, rpy, axis } =
        &i.joints[0].geometry
    else {
        panic!("not an origin joint");
    };
    use planar_arm_core::ring::int;
    use planar_arm_core::Poly;
    // (1, 0, 0) + Rz(90) (2, 0, 0) = (1, 2, 0).
    assert_eq!(
        xyz,
        &[
            Poly::constant(int(1)),
            Poly::constant(int(2)),
            Poly::default()
        ]
    );
    // Rz(90) then xyaxes (x = -y, y = x), a turn of -90 about z: no turn at all.
    assert!(rpy
        .iter()
        .all(|a| *a == planar_arm_core::mechanics::spatial::FixedAngle::zero()));
    assert_eq!(axis[0], Poly::constant(int(1)));
}

#[test]
fn default_classes_and_childclass_supply_attributes() {
    let p = file(
        "classes.xml",
        "<mujoco>\n<default>\n<joint damping=\"0.5\"/>\n<default class=\"arm\">\n\
         <joint axis=\"0 1 0\" armature=\"0.1\"/>\n<geom type=\"capsule\" size=\"0.05\" fromto=\"0 0 0 0 0 1\" mass=\"2\"/>\n\
         </default>\n</default>\n<worldbody>\n<body name=\"a\" childclass=\"arm\">\n<joint name=\"j\"/>\n\
         <geom/>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    let i = import(Format::Mjcf, &p, None, None).unwrap();
    use planar_arm_core::ring::{int, ratio};
    use planar_arm_core::Poly;
    let j = &i.joints[0];
    // damping from main, armature and axis from `arm`, the geom's mass and fromto too.
    assert_eq!(j.damping, Poly::constant(ratio(1, 2)));
    assert_eq!(j.armature, Poly::constant(ratio(1, 10)));
    assert_eq!(j.mass, Poly::constant(int(2)));
    assert_eq!(j.com[2], Poly::constant(ratio(1, 2)));
    let planar_arm_core::mechanics::spatial::SpatialGeometry::Urdf { axis, .. } = &j.geometry
    else {
        panic!("not an origin joint");
    };
    assert_eq!(axis[1], Poly::constant(int(1)));
}

#[test]
fn an_inertial_with_both_a_tensor_and_an_orientation_is_refused_as_mujoco_does() {
    let p = file(
        "both.xml",
        "<mujoco>\n<worldbody>\n<body name=\"a\"><joint/>\n\
         <inertial pos=\"0 0 0\" euler=\"0 0 90\" mass=\"1\" fullinertia=\"1 2 3 0 0 0\"/>\n\
         </body>\n</worldbody>\n</mujoco>\n",
    );
    let e = error(Format::Mjcf, &p, None, None);
    assert!(e.starts_with(&format!("{p}:4:1:")), "{e}");
    assert!(e.contains("takes no orientation"), "{e}");
}

fn planar_gravity(path: &str) -> (Rational, Rational) {
    let i = super::import_planar(Format::Mjcf, path, None, None, false).unwrap();
    let (x, y) = &i.planar.gravity;
    (x.as_rational().unwrap(), y.as_rational().unwrap())
}

#[test]
fn gravity_keeps_its_direction_in_the_plane() {
    let g = ratio(981, 100);
    // The acrobot's links stand along z at qpos = 0, the plane's x: gravity points down it.
    assert_eq!(
        planar_gravity("../models/acrobot.xml"),
        (-g.clone(), int(0))
    );
    // The cart-pole's plane has x along the slide and y = n x x = -z: gravity points up y.
    assert_eq!(
        planar_gravity("../models/cartpole.xml"),
        (int(0), g.clone())
    );
    assert_eq!(planar_gravity("../models/pendulum.xml"), (int(0), g));
}

#[test]
fn a_floating_base_of_slides_at_right_angles_is_turned_by_offsets() {
    // The hopper: slides along x and z, then hinges about y; the plane's x is the first
    // slide, y = n x x with n = +y is -z, so the second slide is a quarter turn clockwise.
    let i = super::import_planar(Format::Mjcf, "../models/hopper.xml", None, None, false).unwrap();
    let offsets: Vec<String> = i
        .planar
        .links
        .iter()
        .map(|l| {
            l.offset
                .as_ref()
                .map_or("0".into(), |o| o.angle.to_string())
        })
        .collect();
    assert_eq!(offsets[..2], ["0", "-pi/2"], "{offsets:?}");
    assert!(i.planar.links.iter().all(|l| !l.reversed));
    // The slides are massless and of zero length: the torso carries them.
    assert!(i.planar.links[..2]
        .iter()
        .all(|l| l.mass == Poly::constant(int(0)) && l.length == Poly::constant(int(0))));
    assert!(i
        .planar
        .notes
        .iter()
        .any(|n| n.contains("`rootz` by -pi/2")));
}

#[test]
fn what_a_planar_arm_cannot_say_yet_is_named() {
    // The UR5 is not planar: its second axis leaves the first's plane by a right angle.
    let e = match super::import_planar(Format::Urdf, "../models/ur5.urdf", None, None, false) {
        Ok(_) => panic!("the UR5 read as planar"),
        Err(e) => e.0,
    };
    assert!(
        e.contains("joint `shoulder_lift_joint`: its axis") && e.contains("by 90.000 degrees"),
        "{e}"
    );
}

#[test]
fn the_reacher_is_planar_in_its_own_plane() {
    let i = super::import_planar(Format::Mjcf, "../models/reacher.xml", None, None, false).unwrap();
    assert_eq!(i.names, ["shoulder", "wrist"]);
    // Gravity is normal to the plane: none acts.
    assert_eq!(
        i.planar.gravity,
        (Poly::constant(int(0)), Poly::constant(int(0)))
    );
    assert!(
        i.planar.notes[0].contains("normal (0, 0, 1)"),
        "{}",
        i.planar.notes[0]
    );
}
