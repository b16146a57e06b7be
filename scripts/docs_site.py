"""The documentation site: the guide (README.md, docs/*.md and CHANGELOG.md as HTML pages),
the Rust API (rustdoc), the C API (Doxygen) and the Python API (pdoc) in one folder with
one front page, then every link inside it checked. Run by scripts/docs-site, which builds
the parts that need other programs and calls this with the Python of the test environment
(Python-Markdown and pdoc from PyPI, the package rmfsurf installed).

    python scripts/docs_site.py ROOT SITE
    python scripts/docs_site.py --check SITE      only check the links of SITE

ROOT is the repository; SITE already holds rust/ (cargo doc) and c/ (Doxygen). Writes the
guide's pages and python/ into SITE, then checks that every relative link and image of
every HTML page there points at a file of the site — and, for a link with a #fragment into
a guide page, at an element with that id. Exits 1 listing the broken ones. The link
checker is these few lines rather than a link-checking package: the site is files on disk,
so a link is good when the file and the id exist, and nothing needs fetching.
"""

import html
import html.parser
import os
import pathlib
import re
import shutil
import sys
import urllib.parse

import markdown
import pdoc
import pdoc.render

# The repository's address, for links from a guide page to a repository file that is not a
# page of the site (a source file, an example).
BLOB = "https://github.com/rmfsurf/rmfsurf/blob/main/"

# The package's public modules: each must have its page.
PYTHON_MODULES = ("curves", "frames", "surfaces", "shapes", "sheets", "cone_splines", "ocp",
                  "freecad")

NAV = [
    ("index.html", "Overview"),
    ("guide.html", "Guide"),
    ("rust/index.html", "Rust API"),
    ("c/index.html", "C API"),
    ("python/rmfsurf.html", "Python API"),
    ("changelog.html", "Changelog"),
]

STYLE = """
body { font: 16px/1.5 system-ui, sans-serif; max-width: 60em; margin: 0 auto; padding: 0 1em; }
nav { border-bottom: 1px solid #ccc; padding: .6em 0; }
nav a { margin-right: 1.2em; }
pre { background: #f5f5f5; padding: .6em; overflow-x: auto; }
code { font-family: ui-monospace, monospace; font-size: 90%; }
table { border-collapse: collapse; } td, th { border: 1px solid #ccc; padding: .2em .5em; }
img { max-width: 100%; }
"""


def pages(root):
    """(source path, page name) of every guide page: the README as the front page,
    docs/README.md as guide.html, each other docs/*.md by its name, the CHANGELOG."""
    found = [("README.md", "index.html"), ("docs/README.md", "guide.html"),
             ("CHANGELOG.md", "changelog.html")]
    for name in sorted(os.listdir(os.path.join(root, "docs"))):
        if name.endswith(".md") and name != "README.md":
            found.append(("docs/" + name, name[:-3] + ".html"))
    return found


def rewrite_link(target, source, page_of):
    """A guide page's link: to the page it names if that is a page of the site, to an
    image of the site, to the repository for any other repository file; others as they
    are."""
    parts = urllib.parse.urlsplit(target)
    if parts.scheme or parts.netloc or not parts.path:
        return target
    path = os.path.normpath(os.path.join(os.path.dirname(source), parts.path))
    fragment = "#" + parts.fragment if parts.fragment else ""
    if path in page_of:
        return page_of[path] + fragment
    if path.startswith("docs/images/"):
        return "images/" + path[len("docs/images/"):]
    return BLOB + path + fragment


def render_page(root, source, page_of):
    with open(os.path.join(root, source), encoding="utf-8") as f:
        text = f.read()
    heading = re.search(r"^# (.+)$", text, re.M)
    title = heading.group(1) if heading else os.path.basename(source)[:-3]
    body = markdown.markdown(text, extensions=["tables", "fenced_code", "toc"])

    def fix(match):
        attribute, target = match.group(1), html.unescape(match.group(2))
        return '%s="%s"' % (attribute, html.escape(rewrite_link(target, source, page_of)))

    body = re.sub(r'\b(href|src)="([^"]*)"', fix, body)
    nav = " ".join('<a href="%s">%s</a>' % (href, label) for href, label in NAV)
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<title>%s</title><style>%s</style></head><body><nav>%s</nav>\n%s"
            "</body></html>\n" % (html.escape(title), STYLE, nav, body))


def write_guide(root, site):
    found = pages(root)
    page_of = {source: page for source, page in found}
    for source, page in found:
        with open(os.path.join(site, page), "w", encoding="utf-8") as f:
            f.write(render_page(root, source, page_of))
    shutil.copytree(os.path.join(root, "docs", "images"), os.path.join(site, "images"))
    return len(found)


def write_python_api(site):
    """pdoc's pages of rmfsurf and its modules; rmfsurf.freecad imports FreeCAD's own
    modules, found in Debian's FreeCAD library folder."""
    sys.path.append("/usr/lib/freecad-python3/lib")
    import rmfsurf  # noqa: F401  (fails here, not inside pdoc, when it is not installed)
    pdoc.render.configure(docformat="google", footer_text="rmfsurf")
    out = pathlib.Path(site, "python")
    # The adapters are not imported by the package (each needs its CAD program): named.
    pdoc.pdoc("rmfsurf", "rmfsurf.ocp", "rmfsurf.freecad", output_directory=out)
    for module in PYTHON_MODULES:
        if not (out / "rmfsurf" / (module + ".html")).is_file():
            sys.exit("docs-site: pdoc wrote no page for rmfsurf.%s" % module)


class Links(html.parser.HTMLParser):
    """The ids and the href/src targets of one HTML page. A rustdoc page names a script of
    the trait's implementors in other crates (trait.impl/, type.impl/), which rustdoc
    writes only when there are some: such a script is not a link."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids, self.targets = set(), []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("id", "name") and value:
                self.ids.add(value)
            elif name in ("href", "src") and value and tag != "base" and not (
                    tag == "script" and re.search(r"(^|/)(trait|type)\.impl/", value)):
                self.targets.append(value)


def check_links(site, guide_pages):
    parsed, broken, count = {}, [], 0

    def parse(path):
        if path not in parsed:
            links = Links()
            with open(path, encoding="utf-8", errors="replace") as f:
                links.feed(f.read())
            parsed[path] = links
        return parsed[path]

    for folder, _, files in os.walk(site):
        for name in files:
            if not name.endswith(".html"):
                continue
            page = os.path.join(folder, name)
            for target in parse(page).targets:
                parts = urllib.parse.urlsplit(target)
                if parts.scheme or parts.netloc or target.startswith("#") and not parts.path:
                    if target.startswith("#") and os.path.relpath(page, site) in guide_pages \
                            and target[1:] not in parse(page).ids:
                        broken.append((page, target))
                    continue
                count += 1
                path = os.path.normpath(os.path.join(folder, urllib.parse.unquote(parts.path)))
                if os.path.isdir(path):
                    path = os.path.join(path, "index.html")
                if not os.path.isfile(path):
                    broken.append((page, target))
                elif parts.fragment and os.path.relpath(path, site) in guide_pages \
                        and parts.fragment not in parse(path).ids:
                    broken.append((page, target))
    return count, broken


def main():
    if sys.argv[1] == "--check":
        site, guide = sys.argv[2], 0
        guide_pages = {os.path.relpath(os.path.join(folder, n), site)
                       for folder, _, files in os.walk(site) for n in files}
    else:
        root, site = sys.argv[1], sys.argv[2]
        guide = write_guide(root, site)
        write_python_api(site)
        guide_pages = {page for _, page in pages(root)}
    count, broken = check_links(site, guide_pages)
    html_pages = sum(1 for _, _, files in os.walk(site) for n in files if n.endswith(".html"))
    for page, target in broken:
        print("docs-site: broken link in %s: %s" % (os.path.relpath(page, site), target))
    print("docs-site: %d HTML pages (%d guide pages), %d internal links checked, %d broken"
          % (html_pages, guide, count, len(broken)))
    sys.exit(1 if broken else 0)


main()
