//! MJCF's default classes: an attribute an element does not set comes from its class (its own
//! `class`, else the nearest enclosing `childclass`, else `main`), then that class's parents.

use std::collections::BTreeMap;

use roxmltree::Node;

use super::files::Files;

/// Each class: its parent, and its `<default>` elements (several where included files add to
/// `main`).
pub struct Defaults<'a, 't> {
    classes: BTreeMap<String, (Option<String>, Vec<Node<'a, 't>>)>,
}

impl<'a, 't> Defaults<'a, 't> {
    pub fn read(files: &'a Files<'t>, top: &[Node<'a, 't>]) -> Self {
        let mut d = Self {
            classes: BTreeMap::new(),
        };
        for node in top.iter().filter(|n| n.has_tag_name("default")) {
            d.add(files, *node, None);
        }
        d
    }

    fn add(&mut self, files: &'a Files<'t>, node: Node<'a, 't>, parent: Option<&str>) {
        let name = match (node.attribute("class"), parent) {
            (Some(c), _) => c.to_string(),
            (None, _) => "main".to_string(),
        };
        let parent = if name == "main" {
            None
        } else {
            Some(parent.unwrap_or("main").to_string())
        };
        self.classes
            .entry(name.clone())
            .or_insert_with(|| (parent, Vec::new()))
            .1
            .push(node);
        for c in files.elements(node) {
            if c.has_tag_name("default") {
                self.add(files, c, Some(&name));
            }
        }
    }

    /// Attribute `key` of `node` (a `<joint>`, `<geom>`, `<inertial>`...), from the element or
    /// its class `class`.
    pub fn get(
        &self,
        files: &'a Files<'t>,
        node: Node<'a, 't>,
        class: &str,
        key: &str,
    ) -> Option<&'a str> {
        if let Some(v) = node.attribute(key) {
            return Some(v);
        }
        let tag = node.tag_name().name();
        let mut class = node.attribute("class").unwrap_or(class).to_string();
        for _ in 0..64 {
            let (parent, nodes) = self.classes.get(&class)?;
            for d in nodes {
                for e in files.elements(*d) {
                    if e.has_tag_name(tag) {
                        if let Some(v) = e.attribute(key) {
                            return Some(v);
                        }
                    }
                }
            }
            class = parent.clone()?;
        }
        None
    }

    pub fn has(&self, class: &str) -> bool {
        self.classes.contains_key(class)
    }
}
