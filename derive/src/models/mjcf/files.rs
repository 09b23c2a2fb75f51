//! An MJCF model and the files it `<include>`s, parsed once, walked as one document.

use std::path::{Path, PathBuf};

use roxmltree::Node;

use crate::models::tree::{FileError, Loc};
use crate::models::xml::Xml;

/// The texts of the model and of every file it includes, main file first.
pub fn load(path: &str, full: &Path, text: &str) -> Result<Vec<(String, String)>, FileError> {
    let dir = full.parent().map_or_else(PathBuf::new, Path::to_path_buf);
    let mut texts = vec![(path.to_string(), text.to_string())];
    let mut k = 0;
    while k < texts.len() {
        let (shown, text) = texts[k].clone();
        let xml = Xml::parse(&shown, &text)?;
        for inc in xml.doc.descendants().filter(|n| n.has_tag_name("include")) {
            let Some(file) = inc.attribute("file") else {
                return Err(xml.error(inc, "<include> without a `file`"));
            };
            // MuJoCo resolves includes against the main file's directory.
            let name = Path::new(path)
                .parent()
                .map_or_else(|| PathBuf::from(file), |p| p.join(file))
                .display()
                .to_string();
            if texts.iter().any(|(n, _)| *n == name) {
                continue;
            }
            if texts.len() > 64 {
                return Err(xml.error(inc, "more than 64 included files; is an include recursive?"));
            }
            let body = std::fs::read_to_string(dir.join(file))
                .map_err(|e| xml.error(inc, format!("cannot read the included `{file}`: {e}")))?;
            texts.push((name, body));
        }
        k += 1;
    }
    Ok(texts)
}

/// The parsed files.
pub struct Files<'t> {
    pub xmls: Vec<Xml<'t>>,
}

impl<'t> Files<'t> {
    pub fn parse(texts: &'t [(String, String)]) -> Result<Self, FileError> {
        let xmls = texts
            .iter()
            .map(|(p, t)| Xml::parse(p, t))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self { xmls })
    }

    pub fn main(&self) -> &Xml<'t> {
        &self.xmls[0]
    }

    /// The file `node` is in.
    pub fn xml(&self, node: Node<'_, '_>) -> &Xml<'t> {
        self.xmls
            .iter()
            .find(|x| {
                core::ptr::eq(
                    core::ptr::from_ref(node.document()).cast::<u8>(),
                    core::ptr::from_ref(&x.doc).cast::<u8>(),
                )
            })
            .unwrap_or(&self.xmls[0])
    }

    pub fn loc(&self, node: Node<'_, '_>) -> Loc {
        self.xml(node).loc(node)
    }

    pub fn error(&self, node: Node<'_, '_>, message: impl core::fmt::Display) -> FileError {
        self.xml(node).error(node, message)
    }

    /// The element children of `node`, each `<include>` replaced by its file's top-level
    /// elements.
    pub fn elements<'a>(&'a self, node: Node<'a, 't>) -> Vec<Node<'a, 't>> {
        let mut out = Vec::new();
        for c in node.children().filter(Node::is_element) {
            if c.has_tag_name("include") {
                let file = c.attribute("file").unwrap_or_default();
                let base = Path::new(&self.xmls[0].path);
                let name = base
                    .parent()
                    .map_or_else(|| PathBuf::from(file), |p| p.join(file))
                    .display()
                    .to_string();
                if let Some(x) = self.xmls.iter().find(|x| x.path == name) {
                    out.extend(self.elements(x.doc.root_element()));
                }
            } else {
                out.push(c);
            }
        }
        out
    }

    /// Every element of the model, includes expanded, depth first.
    pub fn all<'a>(&'a self, node: Node<'a, 't>) -> Vec<Node<'a, 't>> {
        let mut out = Vec::new();
        for c in self.elements(node) {
            out.push(c);
            out.extend(self.all(c));
        }
        out
    }
}
