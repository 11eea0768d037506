//! Whether an SVG file is a plain drawing that a report may inline although no manifest says
//! that rolldyn wrote it (a folder of an older rolldyn): only the shapes and text elements
//! plots are made of, and no attribute that runs code or fetches anything. Anything else (a
//! `<script>`, an `onload`, an `<iframe>`, a link, a DTD) makes it not plain: it is not
//! inlined. A check, not a rewrite: a file is inlined as it is or not at all.

/// The elements a plot is made of (those of the plotting library and of rolldyn's own SVG).
const PLAIN_ELEMENTS: [&str; 13] = [
    "svg", "g", "rect", "line", "polyline", "polygon", "circle", "ellipse", "path", "text",
    "tspan", "title", "desc",
];

/// Why `svg` (the text from its `<svg` tag on) is not a plain drawing; `None` when it is.
pub fn not_plain(svg: &str) -> Option<String> {
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        rest = &rest[open + 1..];
        if let Some(after) = rest.strip_prefix("!--") {
            let Some(end) = after.find("-->") else {
                return Some("an unclosed comment".into());
            };
            rest = &after[end + 3..];
            continue;
        }
        let tag = rest.strip_prefix('/').unwrap_or(rest);
        let name_end = tag
            .find(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, ':' | '-' | '_')))
            .unwrap_or(tag.len());
        let name = &tag[..name_end];
        if !PLAIN_ELEMENTS.contains(&name) {
            return Some(match name {
                "" => format!("markup <{}", rest.chars().take(8).collect::<String>()),
                _ => format!("a <{name}> element"),
            });
        }
        match attributes(&tag[name_end..]) {
            Ok(end) => rest = &tag[name_end + end..],
            Err(reason) => return Some(reason),
        }
    }
    None
}

/// Reads the attributes of a tag up to its `>` and returns the length read; or why one of them
/// is not plain (an event handler, a link or a reference to anything outside the drawing).
fn attributes(text: &str) -> Result<usize, String> {
    let mut at = 0;
    let bytes = text.as_bytes();
    loop {
        while at < bytes.len() && (bytes[at].is_ascii_whitespace() || bytes[at] == b'/') {
            at += 1;
        }
        match bytes.get(at) {
            None => return Err("an unclosed tag".into()),
            Some(b'>') => return Ok(at + 1),
            _ => {}
        }
        let start = at;
        while at < bytes.len()
            && !matches!(bytes[at], b'=' | b'>' | b'/')
            && !bytes[at].is_ascii_whitespace()
        {
            at += 1;
        }
        let name = text[start..at].to_ascii_lowercase();
        while at < bytes.len() && bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        let mut value = "";
        if bytes.get(at) == Some(&b'=') {
            at += 1;
            while at < bytes.len() && bytes[at].is_ascii_whitespace() {
                at += 1;
            }
            let Some(&quote) = bytes.get(at).filter(|q| matches!(**q, b'"' | b'\'')) else {
                return Err(format!("the unquoted attribute {name}"));
            };
            let Some(len) = text[at + 1..].find(quote as char) else {
                return Err(format!("the unclosed attribute {name}"));
            };
            value = &text[at + 1..at + 1 + len];
            at += len + 2;
        }
        let lower = value.to_ascii_lowercase();
        if name.starts_with("on")
            || name.ends_with("href")
            || name == "src"
            || name == "style"
            || lower.contains("javascript:")
            || lower.contains("url(")
        {
            return Err(format!("the attribute {name}"));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::not_plain;

    #[test]
    fn a_plot_is_plain() {
        let plot = "<svg width=\"10\" height=\"10\" xmlns=\"http://www.w3.org/2000/svg\">\
                    <!-- axes --><rect x=\"0\" y=\"0\" width=\"5\" height=\"5\" fill=\"#FFFFFF\"/>\
                    <text x=\"1\" y=\"2\" font-family=\"sans-serif\">p &lt; 5 MPa</text>\
                    <polyline fill=\"none\" points=\"0,0 1,1\"/></svg>";
        assert_eq!(not_plain(plot), None);
    }

    #[test]
    fn n5_scripts_handlers_frames_and_links_are_not_plain() {
        for (svg, reason) in [
            ("<svg><script>alert(1)</script></svg>", "<script>"),
            ("<svg onload=\"alert(1)\"></svg>", "onload"),
            ("<svg><rect ONCLICK='x()'/></svg>", "onclick"),
            (
                "<svg><foreignObject><iframe src=\"http://x\"/></foreignObject></svg>",
                "<foreignObject>",
            ),
            ("<svg><iframe src=\"http://x\"></iframe></svg>", "<iframe>"),
            (
                "<svg><a href=\"javascript:x()\"><text>t</text></a></svg>",
                "<a>",
            ),
            ("<svg><rect fill=\"url(http://x/p.svg#g)\"/></svg>", "fill"),
            ("<svg><rect style=\"background:url(x)\"/></svg>", "style"),
            ("<svg><![CDATA[ x ]]></svg>", "markup"),
            ("<svg><rect x=1 /></svg>", "unquoted"),
            (
                "<svg><rect title=\"a > b\" onmouseover=\"x()\"/></svg>",
                "onmouseover",
            ),
        ] {
            let why = not_plain(svg).unwrap_or_else(|| panic!("{svg} passed"));
            assert!(why.contains(reason), "{svg}: {why}");
        }
    }
}
