#include "report/document.hpp"

#include <cctype>
#include <sstream>

#include "report/text.hpp"

namespace cairn::report {

void Document::heading(int level, std::string text) {
    Block b;
    b.kind = Block::Kind::heading;
    b.level = level;
    b.text = std::move(text);
    blocks.push_back(std::move(b));
}
void Document::paragraph(std::string text) {
    Block b;
    b.text = std::move(text);
    blocks.push_back(std::move(b));
}
void Document::bullets(std::vector<std::string> items) {
    Block b;
    b.kind = Block::Kind::bullets;
    b.items = std::move(items);
    blocks.push_back(std::move(b));
}
void Document::table(Table t) {
    Block b;
    b.kind = Block::Kind::table;
    b.table = std::move(t);
    blocks.push_back(std::move(b));
}
namespace {
/// a block showing the file at `path` (relative to the document) with its caption
Block file_block(Block::Kind kind, std::string path, std::string caption) {
    Block b;
    b.kind = kind;
    b.image = std::move(path);
    b.text = std::move(caption);
    return b;
}
}  // namespace

void Document::image(std::string path, std::string caption) {
    blocks.push_back(file_block(Block::Kind::image, std::move(path), std::move(caption)));
}

void Document::page(std::string path, std::string caption) {
    blocks.push_back(file_block(Block::Kind::page, std::move(path), std::move(caption)));
}

void Document::contents() {
    Block b;
    b.kind = Block::Kind::contents;
    blocks.push_back(std::move(b));
}

void append(Document& into, const Document& from, const std::string& image_prefix) {
    for (Block b : from.blocks) {
        if (b.kind == Block::Kind::image || b.kind == Block::Kind::page) b.image = image_prefix + b.image;
        into.blocks.push_back(std::move(b));
    }
}

namespace {

std::string md_cell(const std::string& s) {
    std::string o;
    for (char c : s) o += c == '|' ? std::string("\\|") : std::string(1, c);
    return o;
}

std::string esc(const std::string& s) { return html_text(s); }

const char* cell_class(const std::string& s) {
    if (s.rfind("miss", 0) == 0 || s.rfind("failed", 0) == 0 || s.rfind("unstable", 0) == 0) return " class=\"miss\"";
    if (s.rfind("pass", 0) == 0) return " class=\"pass\"";
    if (s.rfind("cannot", 0) == 0 || s.rfind("not comparable", 0) == 0 || s.rfind("n.c.", 0) == 0) return " class=\"na\"";
    return "";
}

std::string link_of(const Table& t, size_t row, size_t col) {
    if (row >= t.links.size() || col >= t.links[row].size()) return "";
    return t.links[row][col];
}

}  // namespace

std::string anchor_of(const std::string& heading) {
    std::string a;
    for (unsigned char c : heading) {
        if (c == ' ') a += '-';
        else if (std::isalnum(c) || c == '-' || c == '_') a += char(std::tolower(c));
    }
    return a;
}

std::string to_markdown(const Document& d) {
    std::ostringstream o;
    o << "# " << d.title << "\n\n";
    for (const auto& b : d.blocks) {
        switch (b.kind) {
            case Block::Kind::contents:
                for (size_t i = 0; i < d.blocks.size(); ++i)
                    if (d.blocks[i].kind == Block::Kind::heading && d.blocks[i].level <= 3)
                        o << std::string(size_t(2 * (d.blocks[i].level - 2)), ' ') << "- [" << d.blocks[i].text
                          << "](#" << anchor_of(d.blocks[i].text) << ")\n";
                o << "\n";
                break;
            case Block::Kind::heading: o << std::string(size_t(b.level), '#') << " " << b.text << "\n\n"; break;
            case Block::Kind::paragraph: o << b.text << "\n\n"; break;
            case Block::Kind::bullets:
                for (const auto& i : b.items) o << "- " << i << "\n";
                o << "\n";
                break;
            case Block::Kind::table: {
                o << "|";
                for (const auto& h : b.table.header) o << " " << md_cell(h) << " |";
                o << "\n|";
                for (size_t i = 0; i < b.table.header.size(); ++i) o << "---|";
                o << "\n";
                for (size_t ri = 0; ri < b.table.rows.size(); ++ri) {
                    const auto& r = b.table.rows[ri];
                    o << "|";
                    for (size_t ci = 0; ci < r.size(); ++ci) {
                        const std::string link = link_of(b.table, ri, ci);
                        if (link.empty()) o << " " << md_cell(r[ci]) << " |";
                        else o << " [" << md_cell(r[ci]) << "](#" << anchor_of(link) << ") |";
                    }
                    o << "\n";
                }
                o << "\n";
                break;
            }
            case Block::Kind::image: o << "![" << b.text << "](" << b.image << ")\n\n*" << b.text << "*\n\n"; break;
            case Block::Kind::page: o << "[" << b.text << "](" << b.image << ")\n\n"; break;
        }
    }
    return o.str();
}

std::string to_html(const Document& d) {
    std::ostringstream o;
    o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(d.title)
      << "</title>\n<style>\nbody{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}\n"
         "table{border-collapse:collapse;margin:0.5em 0 1.5em;font-size:0.9em}\n"
         "td,th{border:1px solid #bbb;padding:3px 7px;text-align:left;vertical-align:top}\n"
         "th{background:#eee}td.pass{background:#d8f0d8}td.miss{background:#f6d0d0;font-weight:bold}\n"
         "td.na{background:#eee;color:#666}img{max-width:100%;border:1px solid #ccc}\n"
         "figcaption{font-style:italic;margin-bottom:1.5em}\nul.toc{list-style:none;padding-left:0}li.toc3{padding-left:1.5em}\n</style></head><body>\n";
    o << "<h1>" << esc(d.title) << "</h1>\n";
    for (size_t k = 0; k < d.blocks.size(); ++k) {
        const Block& b = d.blocks[k];
        switch (b.kind) {
            case Block::Kind::contents: {
                o << "<nav><ul class=\"toc\">\n";
                for (size_t i = 0; i < d.blocks.size(); ++i)
                    if (d.blocks[i].kind == Block::Kind::heading && d.blocks[i].level <= 3)
                        o << "<li class=\"toc" << d.blocks[i].level << "\"><a href=\"#" << esc(anchor_of(d.blocks[i].text)) << "\">"
                          << esc(d.blocks[i].text) << "</a></li>\n";
                o << "</ul></nav>\n";
                break;
            }
            case Block::Kind::heading:
                o << "<h" << b.level << " id=\"" << esc(anchor_of(b.text)) << "\">" << esc(b.text) << "</h" << b.level << ">\n";
                break;
            case Block::Kind::paragraph: o << "<p>" << esc(b.text) << "</p>\n"; break;
            case Block::Kind::bullets:
                o << "<ul>\n";
                for (const auto& i : b.items) o << "<li>" << esc(i) << "</li>\n";
                o << "</ul>\n";
                break;
            case Block::Kind::table:
                o << "<table>\n<tr>";
                for (const auto& h : b.table.header) o << "<th>" << esc(h) << "</th>";
                o << "</tr>\n";
                for (size_t ri = 0; ri < b.table.rows.size(); ++ri) {
                    const auto& r = b.table.rows[ri];
                    o << "<tr>";
                    for (size_t ci = 0; ci < r.size(); ++ci) {
                        const std::string link = link_of(b.table, ri, ci);
                        o << "<td" << cell_class(r[ci]) << ">";
                        if (link.empty()) o << esc(r[ci]);
                        else o << "<a href=\"#" << esc(anchor_of(link)) << "\">" << esc(r[ci]) << "</a>";
                        o << "</td>";
                    }
                    o << "</tr>\n";
                }
                o << "</table>\n";
                break;
            case Block::Kind::image:
                o << "<figure><img src=\"" << esc(b.image) << "\" alt=\"" << esc(b.text) << "\"><figcaption>"
                  << esc(b.text) << "</figcaption></figure>\n";
                break;
            case Block::Kind::page:
                o << "<figure><iframe src=\"" << esc(b.image) << "\" title=\"" << esc(b.text)
                  << "\" loading=\"lazy\" style=\"width: 100%; height: 460px; border: 0\"></iframe><figcaption><a href=\""
                  << esc(b.image) << "\">" << esc(b.text) << "</a></figcaption></figure>\n";
                break;
        }
    }
    o << "</body></html>\n";
    return o.str();
}

}  // namespace cairn::report
