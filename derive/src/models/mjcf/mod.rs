//! MJCF, as MuJoCo's compiler reads it, for what a chain's rigid-body dynamics depends on:
//! nested bodies and `<frame>`s with their position and orientation, `hinge` and `slide` joints
//! (`pos`, `axis`, `ref`, `range`, `armature`, `damping`, `frictionloss`, `stiffness`,
//! `springref`), `<inertial>` or the
//! geoms' mass properties, default classes and `childclass`, `<include>`, `<compiler angle
//! eulerseq inertiafromgeom autolimits>` and `<option gravity>`.
//!
//! A body's joints move about axes through their `pos`: the link frame of a joint is placed
//! there, and `ref` is folded into it, so that `q` is MuJoCo's `qpos` exactly.

mod defaults;
mod files;
mod inertia;
mod orientation;

use std::path::Path;

use planar_arm_core::mechanics::spatial::FixedAngle;
use planar_arm_core::ring::{int, Rational};
use planar_arm_core::JointKind;
use roxmltree::Node;

use self::defaults::Defaults;
use self::files::Files;
use self::orientation::{orientation, Compiler};
use super::frame::{decimal, Inertial, Pose, Rotation, Vec3};
use super::tree::{Body, Coupling, FileError, Joint, Loc, Motion, Tree};

/// An element's attributes, its own or its class's.
pub struct Attrs<'a, 't> {
    files: &'a Files<'t>,
    defaults: &'a Defaults<'a, 't>,
    pub node: Node<'a, 't>,
    class: String,
}

impl<'a, 't> Attrs<'a, 't> {
    pub fn new(
        files: &'a Files<'t>,
        defaults: &'a Defaults<'a, 't>,
        node: Node<'a, 't>,
        class: &str,
    ) -> Self {
        Self {
            files,
            defaults,
            node,
            class: class.to_string(),
        }
    }

    pub fn get(&self, key: &str) -> Option<&'a str> {
        self.defaults.get(self.files, self.node, &self.class, key)
    }

    pub fn numbers(&self, key: &str, n: usize) -> Result<Option<Vec<Rational>>, FileError> {
        self.files
            .xml(self.node)
            .numbers_in(self.node, key, self.get(key), n)
    }

    pub fn triple(&self, key: &str) -> Result<Option<[Rational; 3]>, FileError> {
        Ok(self
            .numbers(key, 3)?
            .map(|v| [v[0].clone(), v[1].clone(), v[2].clone()]))
    }

    pub fn number(&self, key: &str) -> Result<Option<Rational>, FileError> {
        Ok(self.numbers(key, 1)?.map(|mut v| v.remove(0)))
    }

    pub fn error(&self, message: impl core::fmt::Display) -> FileError {
        self.files.error(self.node, message)
    }

    pub fn loc(&self) -> Loc {
        self.files.loc(self.node)
    }
}

/// Reads the model at `path` (shown in errors; `full` on disk).
pub fn read(path: &str, full: &Path, text: &str) -> Result<Tree, FileError> {
    let texts = files::load(path, full, text)?;
    let files = Files::parse(&texts)?;
    let root = files.main().doc.root_element();
    if !root.has_tag_name("mujoco") {
        return Err(files.error(root, "an MJCF file's root element is <mujoco>"));
    }
    let top = files.elements(root);
    let defaults = Defaults::read(&files, &top);
    let mut compiler = Compiler {
        degrees: true,
        eulerseq: "xyz".to_string(),
    };
    let mut from_geoms = "auto".to_string();
    let mut autolimits = true;
    let mut balance = false;
    for c in top.iter().filter(|n| n.has_tag_name("compiler")) {
        match c.attribute("angle") {
            Some("radian") => compiler.degrees = false,
            Some("degree") | None => {}
            Some(other) => {
                return Err(files.error(
                    *c,
                    format!("`angle=\"{other}\"`: expected degree or radian"),
                ))
            }
        }
        if let Some(seq) = c.attribute("eulerseq") {
            if seq.len() != 3 || !seq.chars().all(|ch| "xyzXYZ".contains(ch)) {
                return Err(files.error(
                    *c,
                    format!("`eulerseq=\"{seq}\"`: three of x, y, z, X, Y, Z"),
                ));
            }
            compiler.eulerseq = seq.to_string();
        }
        if let Some(v) = c.attribute("inertiafromgeom") {
            from_geoms = v.to_string();
        }
        if let Some(v) = c.attribute("autolimits") {
            autolimits = v == "true";
        }
        if let Some(v) = c.attribute("balanceinertia") {
            balance = v == "true";
        }
        for key in ["settotalmass", "boundmass", "boundinertia"] {
            if c.attribute(key)
                .is_some_and(|v| v != "false" && v != "-1" && v != "0")
            {
                return Err(files.error(
                    *c,
                    format!("`{key}` changes the masses MuJoCo uses and is not read; write the masses in the file"),
                ));
            }
        }
    }
    let mut reader = Reader {
        files: &files,
        defaults: &defaults,
        compiler: &compiler,
        from_geoms: &from_geoms,
        autolimits,
        balance,
        tree: Tree::default(),
    };
    reader.tree.gravity = Some(gravity(&files, &top)?);
    reader.tree.bodies.push(Body {
        name: "world".to_string(),
        parent: None,
        origin: Pose::identity(),
        motion: Motion::Fixed,
        inertial: None,
        loc: files.loc(root),
    });
    for w in top.iter().filter(|n| n.has_tag_name("worldbody")) {
        reader.children(*w, 0, &Pose::identity(), "main")?;
    }
    reader.couplings(&top);
    reader.tree.ignored.push(
        "Read from the file: bodies, joints and mass properties. Not read, as they do not change \
         the chain's rigid-body dynamics: visual and collision settings, sites, cameras, lights, \
         sensors, assets, actuators and their gear, contact and fluid settings."
            .to_string(),
    );
    Ok(reader.tree)
}

/// `<option gravity>`, zero where `<flag gravity="disable"/>`.
fn gravity(files: &Files<'_>, top: &[Node<'_, '_>]) -> Result<Vec3, FileError> {
    let mut g = [int(0), int(0), Rational::new((-981).into(), 100.into())];
    for o in top.iter().filter(|n| n.has_tag_name("option")) {
        if let Some(v) = files.xml(*o).triple(*o, "gravity")? {
            g = v;
        }
        for flag in files
            .elements(*o)
            .into_iter()
            .filter(|n| n.has_tag_name("flag"))
        {
            if flag.attribute("gravity") == Some("disable") {
                g = [int(0), int(0), int(0)];
            }
        }
    }
    Ok(g)
}

struct Reader<'a, 't> {
    files: &'a Files<'t>,
    defaults: &'a Defaults<'a, 't>,
    compiler: &'a Compiler,
    from_geoms: &'a str,
    autolimits: bool,
    /// `balanceinertia`: an inertia that breaks the triangle inequality becomes its mean
    /// moment about every axis.
    balance: bool,
    tree: Tree,
}

impl<'a, 't> Reader<'a, 't> {
    /// The bodies and frames inside `node`, hanging from body `parent`; `frame` is `node`'s
    /// placement in `parent`'s frame.
    fn children(
        &mut self,
        node: Node<'a, 't>,
        parent: usize,
        frame: &Pose,
        class: &str,
    ) -> Result<(), FileError> {
        for c in self.files.elements(node) {
            match c.tag_name().name() {
                "body" => self.body(c, parent, frame, class)?,
                "frame" => {
                    let class = c.attribute("childclass").unwrap_or(class).to_string();
                    let at = frame.then(&self.placement(c, &class)?);
                    self.children(c, parent, &at, &class)?;
                }
                "replicate" | "attach" => {
                    return Err(self.files.error(
                        c,
                        format!(
                            "<{}> is not read; expand it into bodies",
                            c.tag_name().name()
                        ),
                    ))
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// `pos` and orientation of a body or frame.
    fn placement(&self, node: Node<'a, 't>, class: &str) -> Result<Pose, FileError> {
        let a = Attrs::new(self.files, self.defaults, node, class);
        let xyz = a.triple("pos")?.unwrap_or_default();
        Ok(Pose::from_rotation(xyz, &orientation(&a, self.compiler)?))
    }

    fn body(
        &mut self,
        node: Node<'a, 't>,
        parent: usize,
        frame: &Pose,
        class: &str,
    ) -> Result<(), FileError> {
        let class = node.attribute("childclass").unwrap_or(class).to_string();
        if !self.defaults.has(&class) && class != "main" {
            return Err(self
                .files
                .error(node, format!("no default class `{class}`")));
        }
        let name = node
            .attribute("name")
            .map_or_else(|| format!("body{}", self.tree.bodies.len()), str::to_string);
        let loc = self.files.loc(node);
        if node.attribute("gravcomp").is_some_and(decimal_is_nonzero) {
            return Err(self.files.error(
                node,
                format!(
                    "body `{name}` has `gravcomp`, a force the arm's dynamics would not include"
                ),
            ));
        }
        let inertial = self.mass_properties(node, &class)?;
        let elements = self.files.elements(node);
        let joints: Vec<Node<'a, 't>> = elements
            .iter()
            .copied()
            .filter(|n| n.has_tag_name("joint") || n.has_tag_name("freejoint"))
            .collect();
        let mut origin = frame.then(&self.placement(node, &class)?);
        let mut parent = parent;
        let mut last_anchor: Vec3 = Default::default();
        for (k, j) in joints.iter().enumerate() {
            let a = Attrs::new(self.files, self.defaults, *j, &class);
            let jname = j
                .attribute("name")
                .map_or_else(|| format!("{name}:joint{k}"), str::to_string);
            let anchor = a.triple("pos")?.unwrap_or_default();
            let (motion, fold) = self.joint(&a, &jname)?;
            let step = Pose {
                xyz: core::array::from_fn(|i| &anchor[i] - &last_anchor[i]),
                rpy: Pose::identity().rpy,
            };
            self.tree.bodies.push(Body {
                name: format!("{name}/{jname}"),
                parent: Some(parent),
                origin: origin.then(&step).then(&fold),
                motion,
                inertial: None,
                loc: a.loc(),
            });
            parent = self.tree.bodies.len() - 1;
            origin = Pose::identity();
            last_anchor = anchor;
        }
        // The body itself, welded where its last joint (if any) leaves it.
        let back = Pose {
            xyz: last_anchor.map(|x| -x),
            rpy: Pose::identity().rpy,
        };
        self.tree.bodies.push(Body {
            name,
            parent: Some(parent),
            origin: origin.then(&back),
            motion: Motion::Fixed,
            inertial,
            loc,
        });
        let me = self.tree.bodies.len() - 1;
        self.children(node, me, &Pose::identity(), &class)
    }

    /// A joint's motion, and the fixed turn or shift that makes `q` equal MuJoCo's `qpos`.
    fn joint(&self, a: &Attrs<'a, 't>, name: &str) -> Result<(Motion, Pose), FileError> {
        let none = Pose::identity();
        let kind = if a.node.has_tag_name("freejoint") {
            "free"
        } else {
            a.get("type").unwrap_or("hinge")
        };
        let kind = match kind {
            "hinge" => JointKind::Revolute,
            "slide" => JointKind::Prismatic,
            "free" | "ball" => {
                return Ok((
                    Motion::Unsupported(format!(
                        "a {kind} joint `{name}`, which a serial arm of hinges and slides cannot represent"
                    )),
                    none,
                ))
            }
            other => return Err(a.error(format!("joint type `{other}`: expected hinge, slide, ball or free"))),
        };
        let axis = a
            .triple("axis")?
            .unwrap_or_else(|| [int(0), int(0), int(1)]);
        if axis.iter().all(num_traits::Zero::is_zero) {
            return Err(a.error(format!("joint `{name}` has a zero axis")));
        }
        let non_negative = |key: &str| -> Result<Rational, FileError> {
            let v = a.number(key)?.unwrap_or_else(|| int(0));
            if num_traits::Signed::is_negative(&v) {
                return Err(a.error(format!("joint `{name}`: a negative `{key}`")));
            }
            Ok(v)
        };
        let limited = match a.get("limited") {
            Some("true") => true,
            Some("false") => false,
            _ => self.autolimits && a.get("range").is_some(),
        };
        let hinge = kind == JointKind::Revolute;
        let range = match a.numbers("range", 2)? {
            Some(r) if limited && r[0] < r[1] => Some(if hinge {
                (self.compiler.radians(&r[0]), self.compiler.radians(&r[1]))
            } else {
                (r[0].clone(), r[1].clone())
            }),
            _ => None,
        };
        let reference = a.number("ref")?.unwrap_or_else(|| int(0));
        let fold = if num_traits::Zero::is_zero(&reference) {
            none
        } else if hinge {
            let af = axis
                .each_ref()
                .map(|x| planar_arm_core::ring::to_f64(x).unwrap_or(0.0));
            let back = FixedAngle {
                radians: -self.compiler.angle(&reference).radians,
                pi_multiple: -self.compiler.angle(&reference).pi_multiple,
            };
            Pose::from_rotation(Default::default(), &Rotation::axis_angle(&af, &back))
        } else {
            // Back along the unit axis by `ref`: exact along a coordinate axis.
            let f = |x: &Rational| planar_arm_core::ring::to_f64(x).unwrap_or(0.0);
            let n = axis.iter().map(|x| f(x) * f(x)).sum::<f64>().sqrt();
            let single = axis
                .iter()
                .filter(|x| !num_traits::Zero::is_zero(*x))
                .count()
                == 1;
            let xyz = axis.clone().map(|x| {
                if single {
                    let sign = if num_traits::Signed::is_negative(&x) {
                        int(1)
                    } else {
                        int(-1)
                    };
                    if num_traits::Zero::is_zero(&x) {
                        int(0)
                    } else {
                        sign * &reference
                    }
                } else {
                    decimal(-f(&x) / n * f(&reference))
                }
            });
            Pose {
                xyz,
                rpy: none.rpy.clone(),
            }
        };
        Ok((
            Motion::Joint(Joint {
                name: name.to_string(),
                kind,
                axis,
                range,
                armature: non_negative("armature")?,
                damping: non_negative("damping")?,
                frictionloss: non_negative("frictionloss")?,
                stiffness: non_negative("stiffness")?,
                // MuJoCo's springref is a qpos, as our q is: no ref folded in.
                springref: match a.number("springref")? {
                    Some(r) if hinge => self.compiler.radians(&r),
                    Some(r) => r,
                    None => int(0),
                },
            }),
            fold,
        ))
    }

    /// The body's `<inertial>`, or its geoms' as `inertiafromgeom` says.
    fn mass_properties(
        &self,
        node: Node<'a, 't>,
        class: &str,
    ) -> Result<Option<Inertial>, FileError> {
        let elements = self.files.elements(node);
        let explicit = elements.iter().find(|n| n.has_tag_name("inertial"));
        let use_geoms = match self.from_geoms {
            "true" => true,
            "false" => false,
            _ => explicit.is_none(),
        };
        if !use_geoms {
            let Some(n) = explicit else {
                return Ok(None);
            };
            let a = Attrs::new(self.files, self.defaults, *n, class);
            let mut body = inertia::inertial(&a, self.compiler)?;
            if inertia::breaks_triangle(&body.inertia) {
                if !self.balance {
                    return Err(a.error(
                        "the inertia breaks the triangle inequality (A + B >= C), which MuJoCo \
                         refuses unless <compiler balanceinertia=\"true\">",
                    ));
                }
                let mean = (&body.inertia[0] + &body.inertia[1] + &body.inertia[2]) / int(3);
                body.inertia = [mean.clone(), mean.clone(), mean, int(0), int(0), int(0)];
            }
            return Ok(Some(body));
        }
        let mut sum: Option<Inertial> = None;
        for g in elements.iter().filter(|n| n.has_tag_name("geom")) {
            if let Some(solid) = inertia::geom(
                &Attrs::new(self.files, self.defaults, *g, class),
                self.compiler,
            )? {
                sum = Some(sum.map_or_else(|| solid.clone(), |s| s.merged(&solid)));
            }
        }
        Ok(sum)
    }

    /// Tendons and equality constraints that tie joints together.
    fn couplings(&mut self, top: &[Node<'a, 't>]) {
        for section in top
            .iter()
            .filter(|n| n.has_tag_name("tendon") || n.has_tag_name("equality"))
        {
            for e in self.files.all(*section) {
                let tag = e.tag_name().name();
                let mut joints: Vec<String> = Vec::new();
                for key in ["joint", "joint1", "joint2"] {
                    joints.extend(e.attribute(key).map(str::to_string));
                }
                for j in self
                    .files
                    .elements(e)
                    .iter()
                    .filter(|n| n.has_tag_name("joint"))
                {
                    joints.extend(j.attribute("joint").map(str::to_string));
                }
                if !joints.is_empty() {
                    self.tree.couplings.push(Coupling {
                        what: format!("<{tag}> in <{}>", section.tag_name().name()),
                        joints,
                        loc: self.files.loc(e),
                    });
                }
            }
        }
    }
}

fn decimal_is_nonzero(text: &str) -> bool {
    super::xml::number(text).is_some_and(|r| !num_traits::Zero::is_zero(&r))
}
