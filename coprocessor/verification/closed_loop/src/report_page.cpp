#include "safecell/closed_loop/report_page.hpp"

namespace safecell {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string report_page_html(const ReportPage& page) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
      escaped(page.title) +
      "</title>\n<style>\n"
      "body{font-family:sans-serif;max-width:1250px;margin:2em auto;color:#222}\n"
      ".verdict{padding:.6em 1em;border-radius:6px;font-weight:bold}\n"
      ".pass{background:#e3f4e1}.fail{background:#f8dddd}\n"
      "table{border-collapse:collapse}td{padding:.2em 1em;border-bottom:1px solid #ddd}\n"
      "figure{margin:1.5em 0}img{max-width:100%;border:1px solid #ccc}\n"
      "</style>\n</head>\n<body>\n<h1>" +
      escaped(page.title) + "</h1>\n<p class=\"verdict " + (page.passed ? "pass" : "fail") + "\">" +
      escaped(page.verdict) +
      "</p>\n<p id=\"missing-pictures\" class=\"verdict fail\" hidden></p>\n<p>" +
      escaped(page.story) + "</p>\n<h2>Figures</h2>\n<table>\n";
  for (const auto& [name, value] : page.figures) {
    html += "<tr><td>" + escaped(name) + "</td><td>" + escaped(value) + "</td></tr>\n";
  }
  html += "</table>\n";
  if (!page.film.path.empty()) {
    html += "<h2>The run</h2>\n<figure><video src=\"" + escaped(page.film.path) +
            "\" controls autoplay loop muted width=\"100%\"></video><figcaption>" +
            escaped(page.film.caption) + "</figcaption></figure>\n";
  }
  html += "<h2>Pictures</h2>\n";
  for (const ReportPicture& picture : page.pictures) {
    html += "<figure><img src=\"" + escaped(picture.path) + "\" alt=\"" + escaped(picture.caption) +
            "\"><figcaption>" + escaped(picture.caption) + "</figcaption></figure>\n";
  }
  // Once the page has loaded: how many pictures did (an attribute a headless browser check reads),
  // and a red line naming those that did not (a folder copied without them).
  html +=
      "<script>\n"
      "window.addEventListener('load', function () {\n"
      "  var images = document.images, missing = [];\n"
      "  for (var i = 0; i < images.length; i++) {\n"
      "    if (!images[i].complete || images[i].naturalWidth === 0) {\n"
      "      missing.push(images[i].getAttribute('src'));\n"
      "    }\n"
      "  }\n"
      "  document.documentElement.setAttribute('data-pictures-loaded',\n"
      "      (images.length - missing.length) + ' of ' + images.length);\n"
      "  if (missing.length > 0) {\n"
      "    var line = document.getElementById('missing-pictures');\n"
      "    line.textContent = 'Pictures that did not load: ' + missing.join(', ');\n"
      "    line.hidden = false;\n"
      "  }\n"
      "});\n"
      "</script>\n";
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace safecell
