//! The properties the importer reads from an element's style: `display`, `visibility` and
//! `transform`, from the presentation attribute, the `<style>` sheets (simplecss selectors)
//! and the `style` attribute, in the cascade's order (CSS 2.2, section 6.4.1): presentation
//! attributes first, then the sheets' rules by specificity and order, then the `style`
//! attribute, then `!important` declarations of the sheets and of the `style` attribute.

use roxmltree::Node;
use simplecss::{AttributeOperator, DeclarationTokenizer, PseudoClass, StyleSheet};

/// The SVG namespace.
pub(super) const SVG_NS: &str = "http://www.w3.org/2000/svg";

/// An element as simplecss matches selectors against it.
#[derive(Clone, Copy)]
struct Matched<'a, 'input>(Node<'a, 'input>);

impl simplecss::Element for Matched<'_, '_> {
    fn parent_element(&self) -> Option<Self> {
        self.0.parent_element().map(Matched)
    }

    fn prev_sibling_element(&self) -> Option<Self> {
        self.0.prev_sibling_element().map(Matched)
    }

    fn has_local_name(&self, name: &str) -> bool {
        self.0.tag_name().name() == name
    }

    fn attribute_matches(&self, local_name: &str, operator: AttributeOperator<'_>) -> bool {
        self.0
            .attributes()
            .find(|a| a.name() == local_name)
            .is_some_and(|a| operator.matches(a.value()))
    }

    fn pseudo_class_matches(&self, class: PseudoClass<'_>) -> bool {
        match class {
            PseudoClass::FirstChild => self.0.prev_sibling_element().is_none(),
            _ => false,
        }
    }
}

/// The rules of every `<style>` element of the document (type text/css or none), in
/// document order.
pub(super) struct Sheets<'a> {
    sheet: StyleSheet<'a>,
}

impl<'a> Sheets<'a> {
    /// The rules of the document's `<style>` elements.
    pub(super) fn of(document: &'a roxmltree::Document<'a>) -> Sheets<'a> {
        let mut sheet = StyleSheet::new();
        for node in document.descendants().filter(|n| is_svg(n, "style")) {
            let css = node
                .attribute("type")
                .is_none_or(|t| t.trim() == "text/css");
            if !css {
                continue;
            }
            for text in node.children().filter_map(|c| c.text()) {
                sheet.parse_more(text);
            }
        }
        Sheets { sheet }
    }

    /// The value of property `name` of `node` after the cascade, or `None` when nothing sets
    /// it.
    pub(super) fn property<'n>(&'n self, node: Node<'n, 'n>, name: &str) -> Option<String> {
        let mut value: Option<String> = node.attribute(name).map(str::to_owned);
        let element = Matched(node);
        // The rules in ascending specificity, document order within the same one.
        let mut matching: Vec<(usize, &simplecss::Rule<'_>)> = self
            .sheet
            .rules
            .iter()
            .enumerate()
            .filter(|(_, rule)| rule.selector.matches(&element))
            .collect();
        matching.sort_by_key(|(k, rule)| (rule.selector.specificity(), *k));
        let inline: Vec<simplecss::Declaration<'_>> = node
            .attribute("style")
            .map(|s| DeclarationTokenizer::from(s).collect())
            .unwrap_or_default();
        for important in [false, true] {
            for (_, rule) in &matching {
                for d in &rule.declarations {
                    if d.name == name && d.important == important {
                        value = Some(d.value.to_owned());
                    }
                }
            }
            for d in &inline {
                if d.name == name && d.important == important {
                    value = Some(d.value.to_owned());
                }
            }
        }
        value.map(|v| v.trim().to_owned())
    }
}

/// Whether `node` is the SVG element `name`: in the SVG namespace, or in none (a file
/// without `xmlns`, which renderers draw as SVG).
pub(super) fn is_svg(node: &Node<'_, '_>, name: &str) -> bool {
    node.is_element() && node.tag_name().name() == name && in_svg(node)
}

/// Whether the element `node` is in the SVG namespace, or in none.
pub(super) fn in_svg(node: &Node<'_, '_>) -> bool {
    node.tag_name().namespace().is_none_or(|ns| ns == SVG_NS)
}
