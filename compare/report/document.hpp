#pragma once
/// A small document model (headings, paragraphs, lists, tables, images) rendered both as Markdown
/// (report.md) and as a self-contained HTML page (index.html), so the two never disagree.

#include <string>
#include <utility>
#include <vector>

namespace cairn::report {

/// A table: header and rows of text cells.
struct Table {
    Table() = default;
    Table(std::vector<std::string> h, std::vector<std::vector<std::string>> r,
          std::vector<std::vector<std::string>> l = {})
        : header(std::move(h)), rows(std::move(r)), links(std::move(l)) {}
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    /// optional per cell: the heading the cell links to (its text, see anchor_of); empty = no link
    std::vector<std::vector<std::string>> links;
};

/// the anchor of a heading: lowercase, spaces to '-', only letters, digits, '-' and '_' kept (as
/// Markdown renderers make it; the HTML page gives its headings the same id)
std::string anchor_of(const std::string& heading);

/// One block of the document.
struct Block {
    enum class Kind { heading, paragraph, bullets, table, image, contents, page } kind = Kind::paragraph;
    int level = 2;                       ///< heading level (1-3)
    std::string text;                    ///< heading, paragraph, image caption
    std::vector<std::string> items;      ///< bullets
    Table table;
    std::string image;                   ///< image (or embedded page) path relative to the document
};

/// The document.
struct Document {
    std::string title;
    std::vector<Block> blocks;
    void heading(int level, std::string text);
    void paragraph(std::string text);
    void bullets(std::vector<std::string> items);
    void table(Table t);
    void image(std::string path, std::string caption);
    /// another HTML page beside the document: a link in Markdown, shown inline (an iframe) in HTML
    void page(std::string path, std::string caption);
    /// a table of contents: links to every level-2 and level-3 heading of the document
    void contents();
};

/// append the blocks of `from` to `into` (not its title), image and page paths prefixed by `image_prefix`
/// (the folder of `from` relative to `into`)
void append(Document& into, const Document& from, const std::string& image_prefix);

/// Markdown text of the document
std::string to_markdown(const Document& d);
/// a self-contained HTML page; cells starting with "miss", "pass" or "not comparable" are coloured
std::string to_html(const Document& d);

}  // namespace cairn::report
