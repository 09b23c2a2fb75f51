//! Arms read from the model files users already have: `#[arm(urdf = "..")]` and
//! `#[arm(mjcf = "..")]`. The file is read at compile time only (the user's program carries no
//! XML parser): parsed into a [`tree::Tree`], cut to the serial [`chain::Chain`] from `base` to
//! `tip`, and handed to the engine as the same exact arm the attributes would write.

pub mod chain;
pub mod frame;
mod mjcf;
pub mod planar;
pub mod tree;
mod urdf;
mod xml;

use std::path::PathBuf;

use planar_arm_core::mechanics::spatial::{
    unit_axis, FixedAngle, SpatialGeometry, SpatialJointSpec,
};
use planar_arm_core::ring::Rational;
use planar_arm_core::Poly;

use num_traits::Zero;
use tree::FileError;

/// The format of a model file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Urdf,
    Mjcf,
}

/// Records `urdf = ".."` (or `mjcf`, by `key`) in `slot`: an error at `lit`, and `false`, when
/// an earlier key already named a file.
pub fn set_file(
    cx: &crate::ctxt::Ctxt,
    slot: &mut Option<(Format, syn::LitStr)>,
    key: &str,
    lit: syn::LitStr,
) -> bool {
    if let Some((_, first)) = slot {
        // #[arm(urdf = "a.urdf", mjcf = "b.xml")]
        cx.error_spanned_by(
            &lit,
            format!(
                "the arm is already read from \"{}\"; an arm comes from one file",
                first.value()
            ),
        );
        return false;
    }
    let format = if key == "urdf" {
        Format::Urdf
    } else {
        Format::Mjcf
    };
    *slot = Some((format, lit));
    true
}

/// The fields of a struct whose links (or joints, `what`) come from a model file: none may be
/// one. `None` after the error, at the derive's struct or at the offending field.
pub fn other_fields<'a>(
    cx: &crate::ctxt::Ctxt,
    input: &'a syn::DeriveInput,
    derive: &str,
    what: &str,
) -> Option<Vec<&'a syn::Field>> {
    let syn::Data::Struct(s) = &input.data else {
        cx.error_spanned_by(
            &input.ident,
            format!("#[derive({derive})] reads a model file into a struct: write `struct Name;`"),
        );
        return None;
    };
    let mut others = Vec::new();
    for field in &s.fields {
        if crate::ast::joint_kind(&field.ty).is_some()
            || field.attrs.iter().any(|a| a.path().is_ident("arm"))
        {
            // #[arm(urdf = "..")] struct Ur5 { #[arm(dh(..))] waist: Revolute }
            cx.error_spanned_by(
                field,
                format!(
                    "the {what}s come from the model file; remove this {what} field (or the \
                     `urdf`/`mjcf` key)"
                ),
            );
            return None;
        }
        others.push(field);
    }
    Some(others)
}

/// What a spatial arm takes from its file.
pub struct Imported {
    pub joints: Vec<SpatialJointSpec>,
    /// The joints' names in the file, in order.
    pub names: Vec<String>,
    pub tool_xyz: [Poly; 3],
    pub tool_rpy: [FixedAngle; 3],
    /// Gravity as the file states it (MJCF's `<option gravity>`), if it does.
    pub gravity: Option<[Poly; 3]>,
    /// The file's absolute path, so that the user's crate rebuilds when it changes.
    pub path: PathBuf,
    /// Notes for the generated docs: locked joints, what was ignored.
    pub notes: Vec<String>,
}

/// The file `path` names, relative to the crate's `Cargo.toml`.
fn resolve(path: &str) -> PathBuf {
    let dir = std::env::var_os("CARGO_MANIFEST_DIR").map_or_else(PathBuf::new, PathBuf::from);
    dir.join(path)
}

fn consts(v: &[planar_arm_core::ring::Rational; 3]) -> [Poly; 3] {
    v.clone().map(Poly::constant)
}

/// The tree of the file at `path` and the file's absolute path.
fn read(format: Format, path: &str) -> Result<(tree::Tree, PathBuf), FileError> {
    let full = resolve(path);
    let text = std::fs::read_to_string(&full).map_err(|e| {
        FileError(format!(
            "cannot read `{path}` ({e}); the path is relative to the crate's Cargo.toml, here {}",
            full.display()
        ))
    })?;
    let tree = match format {
        Format::Urdf => urdf::read(&xml::Xml::parse(path, &text)?)?,
        Format::Mjcf => mjcf::read(path, &full, &text)?,
    };
    Ok((tree, full))
}

/// The notes every import makes: what was locked, what was not read.
fn notes(tree: &tree::Tree, chain: &chain::Chain) -> Vec<String> {
    let mut notes = Vec::new();
    if !chain.locked.is_empty() {
        notes.push(format!(
            "Locked at zero and merged into the link they hang from: {}.",
            chain
                .locked
                .iter()
                .map(|n| format!("`{n}`"))
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    notes.extend(tree.ignored.iter().cloned());
    notes
}

/// What a planar arm takes from its file.
pub struct PlanarImport {
    pub planar: planar::Planar,
    pub names: Vec<String>,
    pub path: PathBuf,
}

/// Reads `path` as a planar arm: the chain from `base` to `tip` in the plane of its hinges,
/// under the file's gravity (URDF's: `0 0 -9.81`) unless `own_gravity`.
pub fn import_planar(
    format: Format,
    path: &str,
    base: Option<&str>,
    tip: Option<&str>,
    own_gravity: bool,
) -> Result<PlanarImport, FileError> {
    let (tree, full) = read(format, path)?;
    let chain = chain::chain(&tree, path, base, tip)?;
    let down = Rational::new((-981).into(), 100.into());
    let g = tree
        .gravity
        .clone()
        .unwrap_or_else(|| [Rational::zero(), Rational::zero(), down]);
    let mut planar = planar::planar(&chain, path, (!own_gravity).then_some(&g))?;
    planar.notes.extend(notes(&tree, &chain));
    Ok(PlanarImport {
        planar,
        names: chain.joints.iter().map(|j| j.joint.name.clone()).collect(),
        path: full,
    })
}

/// Reads `path` and takes the chain from `base` to `tip`.
pub fn import(
    format: Format,
    path: &str,
    base: Option<&str>,
    tip: Option<&str>,
) -> Result<Imported, FileError> {
    let (tree, full) = read(format, path)?;
    let chain = chain::chain(&tree, path, base, tip)?;
    let notes = notes(&tree, &chain);
    let names = chain.joints.iter().map(|j| j.joint.name.clone()).collect();
    let joints = chain
        .joints
        .into_iter()
        .map(|c| SpatialJointSpec {
            geometry: SpatialGeometry::Urdf {
                xyz: consts(&c.origin.xyz),
                rpy: c.origin.rpy,
                axis: unit_axis(&c.joint.axis),
            },
            kind: c.joint.kind,
            mass: Poly::constant(c.body.mass),
            com: consts(&c.body.com),
            inertia: c.body.inertia.map(Poly::constant),
            range: c.joint.range,
            armature: Poly::constant(c.joint.armature),
            damping: Poly::constant(c.joint.damping),
            frictionloss: Poly::constant(c.joint.frictionloss),
            stiffness: Poly::constant(c.joint.stiffness),
            springref: Poly::constant(c.joint.springref),
        })
        .collect();
    Ok(Imported {
        joints,
        names,
        tool_xyz: consts(&chain.tool.xyz),
        tool_rpy: chain.tool.rpy,
        gravity: tree.gravity.as_ref().map(consts),
        path: full,
        notes,
    })
}

#[cfg(test)]
mod tests;
