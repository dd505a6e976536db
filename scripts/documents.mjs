// The site's documents: Markdown files of docs/ as pages of the site, rendered with the pages'
// navigation, so a reader follows a link instead of meeting a repository path. docs/MATH.md is
// www/math.html, the mathematics every page cites; docs/teaching.md is www/teach.html, the
// teacher's kit. scripts/pages.mjs writes them (and checks them) with the pages; `marked` renders
// the Markdown.
import { readFileSync } from "node:fs";
import { Marked } from "marked";

/**
 * @typedef {object} Document
 * @property {string} source its Markdown, from the repository's root
 * @property {string} html its address on the site
 * @property {string} description its `<meta name="description">`
 * @property {string} lead a paragraph after its own first one (HTML), or ""
 * @property {boolean} contents whether it opens with a list of its sections
 * @property {boolean} single whether `make single` writes it too (a document a one-file page links to)
 */

/** @type {readonly Document[]} */
export const DOCUMENTS = [
  {
    source: "docs/MATH.md", html: "math.html", contents: true, single: true,
    description: "The mathematics behind kli, checked: KLI's model and closed form, the Hopf map, the chain through keyframes, the swarm, averaging, synchronisation on a graph and pose graphs (SE-Sync), with reference values.",
    lead: '<p>New to quaternions? The <a href="learn.html">guided tour</a> explains every idea here from the start, each with a live figure.</p>',
  },
  {
    source: "docs/teaching.md", html: "teach.html", contents: false, single: false,
    description: "Teaching with kli: a download of every page and the guided tour that works offline, the tour's figures as SVG, a printed handout, a slide deck and figures for a course page.",
    lead: "",
  },
];

/** A heading's anchor: its words in lower case joined by hyphens (letters of any script kept, so
 *  "S³" and "C²" survive), as GitHub makes them, so the same `#…` works on both. */
export const anchor = (/** @type {string} */ text) =>
  text.toLowerCase().replace(/<[^>]*>/g, "").replace(/[^\p{L}\p{N}\s-]/gu, "").trim().replace(/\s/g, "-");

const escape = (/** @type {string} */ s) => s.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/"/g, "&quot;");

/** The renderer: headings with anchors; tables and code blocks in regions that scroll sideways
 *  on a phone (focusable, named, so a keyboard can scroll them: axe's scrollable-region-focusable). */
function renderer() {
  const marked = new Marked();
  let tables = 0;
  let blocks = 0;
  marked.use({
    renderer: {
      heading({ tokens, depth, text }) {
        const id = anchor(text);
        return `<h${depth} id="${id}">${this.parser.parseInline(tokens)}</h${depth}>\n`;
      },
      table(token) {
        tables += 1;
        const head = token.header.map((cell) => `<th scope="col">${this.parser.parseInline(cell.tokens)}</th>`).join("");
        const rows = token.rows.map((row) =>
          `<tr>${row.map((cell) => `<td>${this.parser.parseInline(cell.tokens)}</td>`).join("")}</tr>`).join("\n");
        return `<div class="scroll" tabindex="0" role="region" aria-label="Table ${tables}">
<table><thead><tr>${head}</tr></thead>
<tbody>
${rows}
</tbody></table></div>\n`;
      },
      code({ text }) {
        blocks += 1;
        return `<pre class="scroll" tabindex="0" role="region" aria-label="Formula ${blocks}"><code>${escape(text)}</code></pre>\n`;
      },
    },
  });
  return marked;
}

/** A document's page: its title and first paragraph as the page's header, the rest as its main
 *  text, `nav` (the pages' navigation) at the header's foot. */
export function documentPage(/** @type {Document} */ doc, /** @type {string} */ nav) {
  const markdown = readFileSync(new URL(`../${doc.source}`, import.meta.url), "utf8");
  const title = /^# (.+)$/m.exec(markdown);
  if (!title) throw new Error(`${doc.source}: no '# title' line`);
  const rest = markdown.slice(title.index + title[0].length).trimStart();
  const split = rest.indexOf("\n\n");
  const [intro, body] = [rest.slice(0, split), rest.slice(split + 2)];
  const marked = renderer();
  const html = (/** @type {string} */ md) => /** @type {string} */ (marked.parse(md));
  const contents = [...body.matchAll(/^## (.+)$/gm)].map(([, heading]) =>
    `<li><a href="#${anchor(heading)}">${marked.parseInline(heading)}</a></li>`);
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="description" content="${escape(doc.description)}">
<link rel="icon" href="data:,">
<link rel="stylesheet" href="style.css">
<style>
.document { max-width: 52rem; line-height: 1.55; }
.document h2 { margin-top: 2rem; }
.document .scroll { overflow-x: auto; max-width: 100%; }
.document pre { background: var(--panel, #f4f4f4); padding: 8px 12px; border-radius: 4px; }
.document td, .document th { padding: 2px 8px; text-align: left; border-bottom: 1px solid #ccc; }
.document code { overflow-wrap: anywhere; }
.document pre code { overflow-wrap: normal; }
</style>
<title>${escape(title[1])}</title>
</head>
<body>
<header class="page-header">
  <h1>${escape(title[1])}</h1>
  ${html(intro).trim()}${doc.lead ? `\n  ${doc.lead}` : ""}
  ${nav}
</header>
<main class="document">
${doc.contents ? `<nav class="contents" aria-label="Contents"><ol>\n${contents.join("\n")}\n</ol></nav>\n` : ""}${html(body)}
</main>
<footer class="page-footer">
  <p>This page is <code>${doc.source}</code> of the project, rendered. The paper: Zinaid Kapić and Aladin Crnkić,
    “Interpolating Rotations with Non-abelian Kuramoto Model on the 3-Sphere”, University of Bihać.</p>
</footer>
</body>
</html>
`;
}
