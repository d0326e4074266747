//! A sheet as A4 pages: blocks (a pane, a table's group of rows, a heading) placed
//! from the top down, each whole on one page, a new page begun where the next block
//! does not fit above the bottom margin, and every page footed with the sheet's
//! title and its number. Each page is a whole SVG document 210 × 297 mm, so that a
//! printer, a PDF and a viewer all take it at its true size.

use crate::label::Label;
use crate::svg_draw::{FONT, MARGIN, PAGE_H, PAGE_W, document, escape, fit_text, text_at};

/// A sheet of one or more A4 pages.
#[derive(Clone, Debug, PartialEq)]
pub struct Sheet {
    /// The sheet's title (the document's title, and every page's foot).
    pub title: String,
    /// The pages in order, each a whole SVG document.
    pub pages: Vec<String>,
}

impl Sheet {
    /// The first page: the whole sheet where it fits on one.
    pub fn first_page(&self) -> &str {
        self.pages.first().map_or("", String::as_str)
    }
}

/// The file of page `index` (from 0) of a sheet written to `path`: the path itself
/// for the first page, `name-2.svg`, `name-3.svg` … for the others.
pub fn page_path(path: &std::path::Path, index: usize) -> std::path::PathBuf {
    if index == 0 {
        return path.to_path_buf();
    }
    let stem = path
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let name = match path.extension() {
        Some(ext) => format!("{stem}-{}.{}", index + 1, ext.to_string_lossy()),
        None => format!("{stem}-{}", index + 1),
    };
    path.with_file_name(name)
}

/// The lowest y a block may reach: the bottom margin, with room for the foot.
pub(crate) const BOTTOM: f64 = PAGE_H - MARGIN;

/// The pages being filled.
pub(crate) struct Pages {
    title: String,
    done: Vec<String>,
    body: String,
    y: f64,
    sections: usize,
}

impl Pages {
    /// A sheet titled `title`, its first page empty.
    pub(crate) fn new(title: &str) -> Self {
        Self {
            title: title.to_owned(),
            done: Vec::new(),
            body: String::new(),
            y: MARGIN,
            sections: 0,
        }
    }

    /// The current page's SVG body, to draw into.
    pub(crate) fn out(&mut self) -> &mut String {
        &mut self.body
    }

    /// The top of a block `height` tall, on this page if it fits above the bottom
    /// margin, else on a new page; the next block starts below it. A block taller
    /// than a page gets a page of its own.
    pub(crate) fn place(&mut self, height: f64) -> f64 {
        if self.y + height > BOTTOM && self.y > MARGIN {
            self.new_page();
        }
        let top = self.y;
        self.y += height;
        top
    }

    /// Begins a new page unless a block `height` tall fits on this one: what keeps a
    /// heading with the block under it.
    pub(crate) fn keep(&mut self, height: f64) {
        if self.y + height > BOTTOM && self.y > MARGIN {
            self.new_page();
        }
    }

    /// The number of the next numbered section (1 for the first).
    pub(crate) fn next_section(&mut self) -> usize {
        self.sections += 1;
        self.sections
    }

    /// Ends the current page; the next block starts at the top of a new one.
    pub(crate) fn new_page(&mut self) {
        self.done.push(std::mem::take(&mut self.body));
        self.y = MARGIN;
    }

    /// The sheet: every page footed with the title and "page i of n".
    pub(crate) fn finish(mut self) -> Sheet {
        if !self.body.is_empty() || self.done.is_empty() {
            self.done.push(std::mem::take(&mut self.body));
        }
        let count = self.done.len();
        let pages = self
            .done
            .iter()
            .enumerate()
            .map(|(i, body)| {
                let foot = foot(&self.title, i + 1, count);
                document(&self.title, &format!("{body}{foot}"), PAGE_H)
            })
            .collect();
        Sheet {
            title: self.title,
            pages,
        }
    }
}

/// A bold heading `size` px, broken into lines at spaces where it is wider than
/// the page.
pub(crate) fn heading(pages: &mut Pages, text: &str, size: f64) {
    let lines = wrap(text, PAGE_W - 2.0 * MARGIN, size);
    let line_h = 1.3 * size;
    let top = pages.place(line_h * lines.len() as f64 + 14.0 - 0.3 * size);
    for (i, l) in lines.iter().enumerate() {
        let y = top + size + 2.0 + line_h * i as f64;
        text_at(pages.out(), [MARGIN, y], l, size, "bold");
    }
}

/// `text` in lines no wider than `width` at `size` px (the approximate measure),
/// broken at spaces; a word wider than a line is cut with an ellipsis.
pub(crate) fn wrap(text: &str, width: f64, size: f64) -> Vec<String> {
    let wide = |t: &str| Label::plain(t).approximate_size(size)[0] > width;
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let joined = if line.is_empty() {
            word.to_owned()
        } else {
            format!("{line} {word}")
        };
        if wide(&joined) && !line.is_empty() {
            lines.push(std::mem::replace(&mut line, word.to_owned()));
        } else {
            line = joined;
        }
    }
    lines.push(line);
    lines.iter().map(|l| fit_text(l, width, size)).collect()
}

/// A page's foot: the title at the left, the page's number at the right, in the
/// bottom margin.
fn foot(title: &str, page: usize, count: usize) -> String {
    let y = PAGE_H - 0.5 * MARGIN;
    let size = 0.8 * FONT;
    let number = if count > 1 {
        format!("{page} / {count}")
    } else {
        String::new()
    };
    format!(
        "<text x=\"{MARGIN:.1}\" y=\"{y:.1}\" font-size=\"{size:.1}\" fill=\"#666666\"{}>{}</text>\n\
         <text x=\"{:.1}\" y=\"{y:.1}\" font-size=\"{size:.1}\" fill=\"#666666\" text-anchor=\"end\">{number}</text>\n",
        crate::svg_draw::family(title),
        escape(&crate::svg_draw::fit_text(
            title,
            PAGE_W - 2.0 * MARGIN - 60.0,
            size
        )),
        PAGE_W - MARGIN
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_that_do_not_fit_start_a_new_page() {
        let mut p = Pages::new("t");
        let usable = BOTTOM - MARGIN;
        assert_eq!(p.place(0.6 * usable), MARGIN);
        // The second block would cross the bottom margin: it starts page 2.
        assert_eq!(p.place(0.6 * usable), MARGIN);
        p.out().push_str("<g/>");
        assert_eq!(p.place(0.3 * usable), MARGIN + 0.6 * usable);
        let sheet = p.finish();
        assert_eq!(sheet.pages.len(), 2);
        for page in &sheet.pages {
            assert!(page.contains("height=\"297.0mm\""), "{page}");
            assert!(page.contains("width=\"210.0mm\""), "{page}");
        }
        assert!(sheet.pages[1].contains("2 / 2"));
    }

    #[test]
    fn later_pages_are_numbered_beside_the_first() {
        let p = std::path::Path::new("out/sheet.svg");
        assert_eq!(page_path(p, 0), p);
        assert_eq!(page_path(p, 2), std::path::Path::new("out/sheet-3.svg"));
    }
}
