//! Reading a model file's XML: positions for errors, numbers exactly.

use planar_arm_core::ring::{parse_decimal, Rational};
use roxmltree::{Document, Node};

use super::tree::{FileError, Loc};

/// A parsed file and the path errors name.
pub struct Xml<'a> {
    pub path: &'a str,
    pub doc: Document<'a>,
}

impl<'a> Xml<'a> {
    pub fn parse(path: &'a str, text: &'a str) -> Result<Self, FileError> {
        let options = roxmltree::ParsingOptions {
            allow_dtd: true,
            ..roxmltree::ParsingOptions::default()
        };
        Document::parse_with_options(text, options)
            .map(|doc| Self { path, doc })
            .map_err(|e| {
                let p = e.pos();
                FileError(format!("{path}:{}:{}: malformed XML: {e}", p.row, p.col))
            })
    }

    /// `path:line:column` of `node`.
    pub fn loc(&self, node: Node<'_, '_>) -> Loc {
        let p = self.doc.text_pos_at(node.range().start);
        format!("{}:{}:{}", self.path, p.row, p.col)
    }

    pub fn error(&self, node: Node<'_, '_>, message: impl core::fmt::Display) -> FileError {
        FileError::at(&self.loc(node), message)
    }

    /// The numbers of attribute `key` (space-separated), exactly; `None` when absent, an error
    /// when it is not `n` numbers (any count when `n` is 0).
    pub fn numbers(
        &self,
        node: Node<'_, '_>,
        key: &str,
        n: usize,
    ) -> Result<Option<Vec<Rational>>, FileError> {
        self.numbers_in(node, key, node.attribute(key), n)
    }

    /// As [`Self::numbers`], of `text`, the value of `key` that `node` has or inherits.
    pub fn numbers_in(
        &self,
        node: Node<'_, '_>,
        key: &str,
        text: Option<&str>,
        n: usize,
    ) -> Result<Option<Vec<Rational>>, FileError> {
        let Some(text) = text else {
            return Ok(None);
        };
        let values: Option<Vec<Rational>> = text.split_whitespace().map(number).collect();
        match values {
            Some(v) if n == 0 || v.len() == n => Ok(Some(v)),
            _ => Err(self.error(
                node,
                format!(
                    "`{key}=\"{text}\"` on <{}>: expected {}",
                    node.tag_name().name(),
                    if n == 1 {
                        "a number".to_string()
                    } else {
                        format!("{n} numbers separated by spaces")
                    }
                ),
            )),
        }
    }

    pub fn triple(
        &self,
        node: Node<'_, '_>,
        key: &str,
    ) -> Result<Option<[Rational; 3]>, FileError> {
        Ok(self
            .numbers(node, key, 3)?
            .map(|v| [v[0].clone(), v[1].clone(), v[2].clone()]))
    }

    pub fn number(&self, node: Node<'_, '_>, key: &str) -> Result<Option<Rational>, FileError> {
        Ok(self.numbers(node, key, 1)?.map(|mut v| v.remove(0)))
    }
}

/// A signed decimal (`-1.5e-3`, `+2`, `.5`), exactly.
pub fn number(text: &str) -> Option<Rational> {
    let (negative, digits) = match text.as_bytes().first()? {
        b'-' => (true, &text[1..]),
        b'+' => (false, &text[1..]),
        _ => (false, text),
    };
    let r = parse_decimal(digits)?;
    Some(if negative { -r } else { r })
}

/// The element children of `node` named `name`.
pub fn children<'a, 'i>(
    node: Node<'a, 'i>,
    name: &'static str,
) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children().filter(move |c| c.has_tag_name(name))
}

pub fn child<'a, 'i>(node: Node<'a, 'i>, name: &'static str) -> Option<Node<'a, 'i>> {
    children(node, name).next()
}

#[cfg(test)]
mod tests {
    use super::*;
    use planar_arm_core::ring::ratio;

    #[test]
    fn numbers_are_exact_and_signed() {
        assert_eq!(number("-1.5e-3"), Some(ratio(-3, 2000)));
        assert_eq!(number("+2"), Some(ratio(2, 1)));
        assert_eq!(number(".5"), Some(ratio(1, 2)));
        assert_eq!(number("0.1x"), None);
        assert_eq!(number(""), None);
    }

    #[test]
    fn errors_name_the_line() {
        let xml = Xml::parse(
            "m.urdf",
            "<robot>\n  <link name=\"a\" x=\"1 2\"/>\n</robot>",
        )
        .unwrap();
        let link = xml.doc.root_element().first_element_child().unwrap();
        let e = xml.triple(link, "x").unwrap_err();
        assert!(
            e.0.starts_with("m.urdf:2:3: `x=\"1 2\"` on <link>"),
            "{}",
            e.0
        );
        let bad = Xml::parse("m.urdf", "<robot>\n<link>\n</robot>")
            .err()
            .unwrap();
        assert!(bad.0.starts_with("m.urdf:3:"), "{}", bad.0);
    }
}
