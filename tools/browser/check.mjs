#!/usr/bin/env node
// Browser test of the built raylemma book, driven by headless Chromium (playwright-core).
//
// Usage: node tools/browser/check.mjs BOOK_DIR [SCREENSHOT_DIR]
//
// Serves BOOK_DIR on 127.0.0.1 (a small static server, below), then visits every page of the
// book (the sidebar's links, every .html file on disk, index.html, print.html) and checks each:
// HTTP 200, no console errors or page errors, no failed or off-machine requests, every <img>
// loaded, every SVG figure's text at least 12 CSS px as shown at the default width, no raw TeX left in the text, <math> present where the chapter's source has math, no
// literal `{{#include`. Then it searches the book with mdBook's search bar and takes screenshots.
// Prints `ok PATH` / `FAIL PATH: reasons` per page and check, and closes with `N passed, M failed`;
// exits 1 on any failure, 2 when it could not run at all.
//
// Environment: CHROMIUM (default /usr/bin/chromium), SEARCH_TERMS (default "Fresnel,Schlick"),
// BOOK_SRC (the chapters' Markdown directory; default: `src` of the book.toml beside BOOK_DIR).

import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const USAGE = 'usage: node tools/browser/check.mjs BOOK_DIR [SCREENSHOT_DIR]';
const NAV_TIMEOUT = 60_000; // generous: CI machines are small
const STEP_TIMEOUT = 30_000;
const LAUNCH_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];
// Pages screenshotted when present, plus every page whose path mentions "renderer".
// The smallest text an SVG figure may show, in CSS px, at the default window width.
const MIN_FIGURE_TEXT_PX = 12;
const viewportWidth = 1280;
const SCREENSHOT_PAGES = ['index.html', 'geometry/sphere.html', 'optics/fresnel.html'];

function die(msg) {
  console.error(`check.mjs: ${msg}`);
  process.exit(2);
}

const args = process.argv.slice(2);
if (args.length < 1 || args.length > 2 || args[0] === '-h' || args[0] === '--help') die(USAGE);
const bookDir = path.resolve(args[0]);
const shotDir = path.resolve(args[1] ?? '/tmp/raylemma-browser');
const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
const searchTerms = (process.env.SEARCH_TERMS || 'Fresnel,Schlick')
  .split(',')
  .map((t) => t.trim())
  .filter(Boolean);

if (!fs.existsSync(path.join(bookDir, 'index.html'))) die(`${bookDir}/index.html not found: build the book first`);
if (!fs.existsSync(chromiumPath)) die(`${chromiumPath} not found (apt-get install chromium, or set CHROMIUM)`);

let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (e) {
  const here = path.dirname(fileURLToPath(import.meta.url));
  die(`playwright-core not installed: run \`npm ci\` in ${here} (${e.message})`);
}

// ---------------------------------------------------------------------------------------------
// Sources: which chapters have math. The book's Markdown is found through the book.toml beside
// the book directory (`[book] src`), or BOOK_SRC. Without it the "has <math>" check is skipped.

function findSourceDir() {
  if (process.env.BOOK_SRC) {
    const dir = path.resolve(process.env.BOOK_SRC);
    if (!fs.statSync(dir, { throwIfNoEntry: false })?.isDirectory()) die(`BOOK_SRC=${dir} is not a directory`);
    return dir;
  }
  const toml = path.join(path.dirname(bookDir), 'book.toml');
  if (!fs.existsSync(toml)) return null;
  const text = fs.readFileSync(toml, 'utf8');
  const book = text.split(/^\[/m).find((s) => s.startsWith('book]'));
  const m = book && book.match(/^\s*src\s*=\s*"([^"]*)"/m);
  const dir = path.join(path.dirname(bookDir), m ? m[1] : 'src');
  return fs.statSync(dir, { throwIfNoEntry: false })?.isDirectory() ? dir : null;
}

// True when Markdown `md` has a formula: `$$` or an inline `$...$`, outside code, `\$` aside.
function markdownHasMath(md) {
  const text = md
    .replace(/^(```|~~~)[^\n]*\n[\s\S]*?^\1[^\n]*$/gm, '') // fenced code blocks
    .replace(/(`+)[\s\S]*?\1/g, '') // inline code
    .replace(/\\\$/g, ''); // literal dollars
  return /\$\$[\s\S]+?\$\$/.test(text) || /\$[^\s$][^$\n]*\$/.test(text);
}

const srcDir = findSourceDir();
const summary = srcDir && fs.existsSync(path.join(srcDir, 'SUMMARY.md'))
  ? fs.readFileSync(path.join(srcDir, 'SUMMARY.md'), 'utf8')
  : null;
// mdBook writes index.html as a copy of the first chapter (unless the book has its own index.md).
const firstChapter = summary && (summary.match(/\]\(([^)]+\.md)\)/) || [])[1];

function sourceFor(page) {
  if (!srcDir) return null;
  let md = page.replace(/\.html$/, '.md');
  if (page === 'index.html' && !fs.existsSync(path.join(srcDir, 'index.md')) && !fs.existsSync(path.join(srcDir, 'README.md'))) {
    md = firstChapter;
  }
  if (!md) return null;
  for (const cand of [md, md.replace(/index\.md$/, 'README.md')]) {
    const p = path.join(srcDir, cand);
    if (fs.existsSync(p)) return p;
  }
  return null;
}

function pageExpectsMath(page) {
  if (page === 'print.html') {
    if (!srcDir) return null;
    return listFiles(srcDir).some((f) => f.endsWith('.md') && markdownHasMath(fs.readFileSync(path.join(srcDir, f), 'utf8')));
  }
  const src = sourceFor(page);
  return src ? markdownHasMath(fs.readFileSync(src, 'utf8')) : null;
}

function listFiles(dir, prefix = '') {
  const out = [];
  for (const ent of fs.readdirSync(dir, { withFileTypes: true })) {
    const rel = prefix ? `${prefix}/${ent.name}` : ent.name;
    if (ent.isDirectory()) out.push(...listFiles(path.join(dir, ent.name), rel));
    else out.push(rel);
  }
  return out.sort();
}

// ---------------------------------------------------------------------------------------------
// Static server: GET/HEAD of files under bookDir, directories serve their index.html.

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg',
  '.gif': 'image/gif',
  '.webp': 'image/webp',
  '.ico': 'image/x-icon',
  '.woff': 'font/woff',
  '.woff2': 'font/woff2',
  '.ttf': 'font/ttf',
  '.otf': 'font/otf',
  '.eot': 'application/vnd.ms-fontobject',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
  '.map': 'application/json',
};

function resolveUnder(root, urlPath) {
  let rel;
  try {
    rel = decodeURIComponent(urlPath.split('?')[0].split('#')[0]);
  } catch {
    return null;
  }
  const full = path.resolve(root, '.' + path.posix.normalize('/' + rel));
  if (full !== root && !full.startsWith(root + path.sep)) return null;
  try {
    const st = fs.statSync(full);
    if (st.isDirectory()) {
      const idx = path.join(full, 'index.html');
      return fs.existsSync(idx) ? idx : null;
    }
    return st.isFile() ? full : null;
  } catch {
    return null;
  }
}

const server = http.createServer((req, res) => {
  const file = req.method === 'GET' || req.method === 'HEAD' ? resolveUnder(bookDir, req.url) : null;
  if (!file) {
    res.writeHead(req.method === 'GET' || req.method === 'HEAD' ? 404 : 405, { 'content-type': 'text/plain' });
    res.end('not found\n');
    return;
  }
  const body = fs.readFileSync(file);
  res.writeHead(200, {
    'content-type': TYPES[path.extname(file).toLowerCase()] || 'application/octet-stream',
    'content-length': body.length,
    'cache-control': 'no-store',
  });
  res.end(req.method === 'HEAD' ? undefined : body);
});
await new Promise((resolve, reject) => {
  server.once('error', reject);
  server.listen(0, '127.0.0.1', resolve);
});
const origin = `http://127.0.0.1:${server.address().port}`;

function servedStatus(urlPath) {
  return resolveUnder(bookDir, urlPath) ? 200 : 404;
}

// ---------------------------------------------------------------------------------------------
// Results.

let passed = 0;
let failed = 0;
function report(name, problems) {
  problems = [...new Set(problems)];
  if (problems.length === 0) {
    passed++;
    console.log(`ok ${name}`);
  } else {
    failed++;
    console.log(`FAIL ${name}: ${problems.join('; ')}`);
  }
}
const short = (s, n = 160) => (s.length > n ? s.slice(0, n) + '…' : s).replace(/\s+/g, ' ');

// ---------------------------------------------------------------------------------------------
// Browser.

const started = Date.now();
const browser = await chromium.launch({ executablePath: chromiumPath, args: LAUNCH_ARGS, headless: true, timeout: NAV_TIMEOUT });
let exitCode = 2;
try {
  const context = await browser.newContext({ viewport: { width: viewportWidth, height: 900 }, deviceScaleFactor: 1 });
  context.setDefaultTimeout(STEP_TIMEOUT);
  context.setDefaultNavigationTimeout(NAV_TIMEOUT);
  // print.html calls window.print() on load; a no-op keeps the headless browser from waiting.
  await context.addInitScript(() => {
    window.print = () => {};
  });
  // Nothing leaves the machine: anything not served by the local server is refused (and reported).
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith(origin + '/') || url.startsWith('data:') || url.startsWith('blob:')) return route.continue();
    return route.abort('blockedbyclient');
  });

  // Opens `page` with listeners that collect problems; returns { tab, problems, status }.
  async function open(pagePath, { query = '' } = {}) {
    const tab = await context.newPage();
    const problems = [];
    tab.on('console', (msg) => {
      if (msg.type() !== 'error') return;
      const at = msg.location()?.url || '';
      problems.push(`console error: ${short(msg.text())}${at ? ` (${at.startsWith(origin) ? at.slice(origin.length) : short(at, 80)})` : ''}`);
    });
    tab.on('pageerror', (err) => problems.push(`page error: ${short(String(err.message || err))}`));
    tab.on('requestfailed', (req) => {
      const url = req.url();
      if (!url.startsWith(origin + '/')) problems.push(`off-machine request refused: ${short(url)}`);
      else problems.push(`request failed: ${url.slice(origin.length)} (${req.failure()?.errorText})`);
    });
    tab.on('response', (resp) => {
      const url = resp.url();
      if (resp.status() >= 400 && url.startsWith(origin + '/') && resp.request().frame() === tab.mainFrame() && !resp.request().isNavigationRequest()) {
        problems.push(`HTTP ${resp.status()} for ${url.slice(origin.length)}`);
      }
    });
    let status = 0;
    try {
      const resp = await tab.goto(`${origin}/${pagePath}${query}`, { waitUntil: 'load', timeout: NAV_TIMEOUT });
      status = resp ? resp.status() : 0;
    } catch (e) {
      problems.push(`navigation failed: ${short(e.message)}`);
    }
    // Problems up to `load` belong to the page; checks other than the page's own look past them.
    return { tab, problems, status, loaded: problems.length };
  }

  // --- Which pages: the sidebar's links (as rendered by mdBook's toc script), plus every .html
  // file on disk except mdBook's fragments.
  const pages = new Set(['index.html']);
  const sidebarPages = [];
  const tocProblems = [];
  {
    const { tab, status } = await open('index.html'); // its own problems are index.html's line
    if (status !== 200) tocProblems.push(`index.html: HTTP ${status}`);
    const hrefs = await tab.evaluate(() => {
      const box = document.querySelector('#mdbook-sidebar, #sidebar, nav.sidebar, .sidebar');
      return box ? [...box.querySelectorAll('a[href]')].map((a) => a.href) : null;
    });
    if (!hrefs) tocProblems.push('no sidebar found on index.html');
    for (const href of hrefs || []) {
      if (!href.startsWith(origin + '/')) continue; // e.g. a repository link
      const rel = decodeURIComponent(new URL(href).pathname.slice(1)) || 'index.html';
      if (!rel.endsWith('.html')) continue;
      if (!sidebarPages.includes(rel)) sidebarPages.push(rel);
      pages.add(rel);
    }
    if (sidebarPages.length === 0) tocProblems.push('the sidebar links to no page');
    await tab.close();
  }
  const fragments = new Set(['toc.html', '404.html']);
  const onDisk = listFiles(bookDir).filter((f) => f.endsWith('.html') && !fragments.has(f));
  for (const f of onDisk) {
    if (!pages.has(f)) pages.add(f);
  }
  // Chapters on disk that the sidebar does not list (print.html and index.html aside).
  const orphans = onDisk.filter((f) => !sidebarPages.includes(f) && f !== 'print.html' && f !== 'index.html');
  if (orphans.length) tocProblems.push(`pages not in the sidebar: ${orphans.join(', ')}`);
  // Chapters in SUMMARY.md that the sidebar does not list.
  if (summary) {
    const listed = [...summary.matchAll(/\]\(([^)#]+\.md)\)/g)].map((m) => m[1].replace(/^\.\//, '').replace(/\.md$/, '.html'));
    const missing = listed.filter((p) => !pages.has(p) && !pages.has(p.replace(/README\.html$/, 'index.html')));
    if (missing.length) tocProblems.push(`SUMMARY.md chapters without a page: ${missing.join(', ')}`);
  }
  const withMath = [...pages].filter((p) => pageExpectsMath(p) === true).length;
  const mathNote = srcDir
    ? `${withMath} with math in their source`
    : 'Markdown sources not found, so <math> presence unchecked';
  report(`table of contents (${sidebarPages.length} sidebar pages, ${pages.size} pages in all, ${mathNote})`, tocProblems);

  // --- Every page.
  const lostVariants = { pages: [], count: new Map() };
  const svgFigures = { count: 0, smallest: Infinity };
  // index.html first, then the sidebar's order, then the rest (print.html) by name.
  const rest = [...pages].filter((p) => p !== 'index.html' && !sidebarPages.includes(p)).sort();
  const ordered = ['index.html', ...sidebarPages.filter((p) => p !== 'index.html'), ...rest];
  for (const pagePath of ordered) {
    const { tab, problems, status } = await open(pagePath);
    if (status !== 200) problems.push(`HTTP ${status}`);
    if (status === 200) {
      // Images: wait until each has settled (loaded or errored), then check it decoded.
      await tab.evaluate(() => {
        for (const img of document.images) if (img.loading === 'lazy') img.loading = 'eager';
      });
      try {
        await tab.waitForFunction(() => [...document.images].every((i) => i.complete), null, { timeout: STEP_TIMEOUT });
      } catch {
        /* reported below */
      }
      const facts = await tab.evaluate(() => {
        const skip = 'code, pre, script, style, noscript, template, textarea, math, svg, #mdbook-searchresults, #searchresults';
        const texts = [];
        const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
        for (let n = walker.nextNode(); n; n = walker.nextNode()) {
          if (n.parentElement && !n.parentElement.closest(skip)) texts.push(n.nodeValue);
        }
        // Text of whole blocks, so that a formula split across inline elements is seen whole.
        const blocks = [...document.querySelectorAll('main p, main li, main td, main th, main h1, main h2, main h3, main h4, main blockquote, main dd, main dt, main figcaption')]
          .filter((el) => !el.querySelector('p, li, blockquote'))
          .map((el) => {
            const clone = el.cloneNode(true);
            for (const c of clone.querySelectorAll(skip)) c.remove();
            return clone.textContent;
          });
        const maths = [...document.querySelectorAll('math')];
        const shownMath = maths.filter((m) => m.checkVisibility());
        const flatMath = shownMath.filter((m) => {
          const r = m.getBoundingClientRect();
          return r.width < 1 || r.height < 1;
        });
        const bodyText = [...document.body.querySelectorAll('*')].length ? document.body.textContent : '';
        const scripts = [...document.querySelectorAll('script')].map((s) => s.textContent).join('\n');
        return {
          texts,
          blocks,
          mathCount: maths.length,
          flatMath: flatMath.map((m) => m.getAttribute('alttext') || m.textContent.slice(0, 60)),
          katexErrors: [...document.querySelectorAll('.katex-error')].map((e) => e.getAttribute('title') || e.textContent),
          includeLeft: /\{\{#(include|rustdoc_include|playground|title)\b/.test(bodyText.replace(scripts, '')),
          badImages: [...document.images]
            .filter((i) => !(i.complete && i.naturalWidth > 0))
            .map((i) => i.getAttribute('src')),
          // MathML Core (Chromium) ignores mathvariant other than "normal": KaTeX's
          // \mathbf, \boldsymbol etc. then show in the plain style. Reported as a note.
          lostVariants: [...document.querySelectorAll('math [mathvariant]:not([mathvariant=normal])')]
            .filter((e) => e.textContent.trim() && !/[\u{1D400}-\u{1D7FF}]/u.test(e.textContent))
            // The book's CSS (assets/book/mathml.css) restores bold: such an element is fine.
            .filter((e) => !(/bold/.test(e.getAttribute('mathvariant')) && parseInt(getComputedStyle(e).fontWeight, 10) >= 600))
            .map((e) => e.getAttribute('mathvariant')),
        };
      });
      if (facts.lostVariants.length) {
        lostVariants.pages.push(pagePath);
        for (const v of facts.lostVariants) lostVariants.count.set(v, (lostVariants.count.get(v) || 0) + 1);
      }
      for (const src of facts.badImages) problems.push(`image not loaded: ${src}`);
      // SVG figures: every text at least MIN_FIGURE_TEXT_PX as displayed (font-size times the
      // image's displayed width over the SVG's own width), and no figure wider than the page.
      const figures = await tab.evaluate(async () => {
        const out = [];
        for (const img of document.images) {
          const src = img.getAttribute('src') || '';
          if (!/\.svg(\?|#|$)/i.test(src) || !img.complete || !img.naturalWidth) continue;
          const shown = img.getBoundingClientRect().width;
          if (!img.checkVisibility() || shown === 0) continue; // mdBook's click-to-enlarge copy, hidden until clicked
          let doc;
          try {
            doc = new DOMParser().parseFromString(await (await fetch(img.src)).text(), 'image/svg+xml');
          } catch (e) {
            out.push({ src, error: String(e) });
            continue;
          }
          const svg = doc.documentElement;
          const own = parseFloat(svg.getAttribute('width')) || (svg.viewBox && svg.viewBox.baseVal && svg.viewBox.baseVal.width) || img.naturalWidth;
          const sizes = [...doc.querySelectorAll('text')]
            .filter((t) => t.textContent.trim())
            .map((t) => parseFloat(t.getAttribute('font-size') || (t.closest('[font-size]') || svg).getAttribute('font-size') || '16'));
          out.push({
            src,
            alt: img.getAttribute('alt') || '',
            shown,
            own,
            texts: sizes.length,
            smallest: sizes.length ? (Math.min(...sizes) * shown) / own : null,
            overflow: img.getBoundingClientRect().right > document.documentElement.clientWidth + 1,
          });
        }
        return out;
      });
      for (const f of figures) {
        if (f.error) problems.push(`figure ${f.src}: ${f.error}`);
        else {
          svgFigures.count += 1;
          if (f.smallest !== null) svgFigures.smallest = Math.min(svgFigures.smallest, f.smallest);
          if (!f.alt.trim()) problems.push(`figure ${f.src}: no alt text`);
          if (f.smallest !== null && f.smallest < MIN_FIGURE_TEXT_PX) {
            problems.push(`figure ${f.src}: text ${f.smallest.toFixed(1)} px as shown (${Math.round(f.shown)} of its ${f.own} px), under ${MIN_FIGURE_TEXT_PX} px`);
          }
          if (f.overflow) problems.push(`figure ${f.src}: wider than the page`);
        }
      }
      const tex = findRawTex([...facts.texts, ...facts.blocks]);
      if (tex.length) problems.push(`raw TeX in text: ${tex.slice(0, 3).map((t) => JSON.stringify(t)).join(', ')}${tex.length > 3 ? ` (+${tex.length - 3} more)` : ''}`);
      if (facts.katexErrors.length) problems.push(`KaTeX errors: ${facts.katexErrors.slice(0, 3).map((e) => short(e, 80)).join(', ')}`);
      if (facts.includeLeft) problems.push('literal {{#include left in the text');
      if (facts.flatMath.length) problems.push(`${facts.flatMath.length} <math> element(s) laid out with no size, e.g. ${JSON.stringify(short(facts.flatMath[0], 60))}`);
      const expects = pageExpectsMath(pagePath);
      if (expects === true && facts.mathCount === 0) problems.push('the source has math but the page has no <math> element');
      if (expects === null && srcDir) problems.push('no Markdown source found for the page');
    }
    // Late console errors (scripts that run after load): give them a moment.
    await tab.waitForTimeout(100);
    await tab.close();
    report(pagePath, problems);
  }

  console.log(
    svgFigures.count
      ? `note: ${svgFigures.count} SVG figures shown, smallest text ${svgFigures.smallest.toFixed(1)} px at a ${viewportWidth} px wide window (minimum ${MIN_FIGURE_TEXT_PX} px)`
      : 'note: no SVG figures in the book',
  );
  if (lostVariants.pages.length) {
    const kinds = [...lostVariants.count].map(([v, n]) => `${n} ${v}`).join(', ');
    console.log(
      `note: Chromium shows MathML mathvariant other than "normal" in the plain style (${kinds}) ` +
        `on ${lostVariants.pages.length} pages, e.g. ${lostVariants.pages.slice(0, 3).join(', ')} (not counted as a failure)`,
    );
  }

  // --- Search: type each term in mdBook's search bar; results must appear, link to existing
  // pages, and the first must open with the term highlighted.
  for (const term of searchTerms) {
    const { tab, problems: all, status, loaded } = await open('index.html');
    const problems = [];
    let summaryText = '';
    let searched = null;
    if (status !== 200) problems.push(`index.html: HTTP ${status}`);
    else {
      try {
        await tab.keyboard.press('s');
        const bar = tab.locator('#mdbook-searchbar, #searchbar').first();
        await bar.waitFor({ state: 'visible', timeout: STEP_TIMEOUT });
        await bar.pressSequentially(term, { delay: 30 });
        const links = tab.locator('#mdbook-searchresults a[href], #searchresults a[href]');
        await links.first().waitFor({ state: 'visible', timeout: STEP_TIMEOUT });
        const hrefs = await links.evaluateAll((as) => as.map((a) => a.href));
        const results = [];
        for (const href of hrefs) {
          const u = new URL(href);
          if (u.origin !== origin) {
            problems.push(`result links off the book: ${href}`);
            continue;
          }
          const rel = decodeURIComponent(u.pathname.slice(1));
          results.push(rel);
          if (servedStatus(u.pathname) !== 200) problems.push(`result links to a missing page: ${rel}`);
        }
        summaryText = `${hrefs.length} results, first ${results[0]}`;
        // Follow the first result as a reader would.
        const first = hrefs[0];
        searched = all.length; // what the result's page logs is on that page's own line
        const [resp] = await Promise.all([
          tab.waitForNavigation({ waitUntil: 'load', timeout: NAV_TIMEOUT }).catch(() => null),
          links.first().click(),
        ]);
        if (!resp || resp.status() !== 200) problems.push(`following ${first} gave ${resp ? `HTTP ${resp.status()}` : 'no navigation'}`);
        else {
          const marks = await tab
            .waitForFunction(() => document.querySelectorAll('main mark').length, null, { timeout: STEP_TIMEOUT })
            .then((h) => h.jsonValue())
            .catch(() => 0);
          if (!marks) problems.push(`the first result's page does not highlight "${term}"`);
        }
      } catch (e) {
        problems.push(`search gave no results: ${short(e.message.split('\n')[0])}`);
      }
    }
    problems.unshift(...all.slice(loaded, searched ?? all.length)); // errors while searching
    await tab.close();
    report(`search "${term}"${summaryText ? ` (${summaryText})` : ''}`, problems);
  }

  // --- Screenshots.
  fs.mkdirSync(shotDir, { recursive: true });
  const shots = SCREENSHOT_PAGES.filter((p) => pages.has(p));
  for (const p of [...pages].sort()) if (/renderer/i.test(p) && !shots.includes(p)) shots.push(p);
  for (const p of SCREENSHOT_PAGES) if (!pages.has(p)) report(`screenshot ${p}`, ['page not in the book']);
  for (const p of shots) {
    const { tab, status } = await open(p); // the page's own problems are on its line
    const problems = [];
    const file = path.join(shotDir, p.replace(/\.html$/, '').replace(/[\\/]/g, '_') + '.png');
    if (status !== 200) problems.push(`HTTP ${status}`);
    else {
      try {
        await tab.evaluate(() => document.fonts.ready.then(() => true));
        await tab.screenshot({ path: file, fullPage: true, timeout: NAV_TIMEOUT });
        if (fs.statSync(file).size < 1000) problems.push('empty screenshot');
      } catch (e) {
        problems.push(`screenshot failed: ${short(e.message)}`);
      }
    }
    await tab.close();
    report(`screenshot ${p} -> ${file}`, problems);
  }
  // A chart on a dark theme (coal): the figure as a reader of that theme sees it.
  {
    const page = 'optics/fresnel.html';
    const { tab, status } = await open(page);
    const problems = [];
    const file = path.join(shotDir, 'figure_coal.png');
    if (status !== 200) problems.push(`HTTP ${status}`);
    else {
      try {
        await tab.evaluate(() => localStorage.setItem('mdbook-theme', 'coal'));
        await tab.reload({ waitUntil: 'load' });
        const img = tab.locator('main img[src$=".svg"]').first();
        await img.scrollIntoViewIfNeeded();
        const theme = await tab.evaluate(() => document.documentElement.classList.contains('coal'));
        if (!theme) problems.push('the coal theme did not apply');
        await img.screenshot({ path: file, timeout: NAV_TIMEOUT });
      } catch (e) {
        problems.push(`screenshot failed: ${short(e.message)}`);
      }
    }
    await tab.close();
    report(`screenshot of a chart on the coal theme (${page}) -> ${file}`, problems);
  }
  exitCode = failed ? 1 : 0;
} finally {
  await browser.close().catch(() => {});
  server.close();
}

console.log(`browser check of ${bookDir} took ${((Date.now() - started) / 1000).toFixed(1)} s`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(exitCode);

// ---------------------------------------------------------------------------------------------
// Raw TeX: what KaTeX would have turned into <math> had it seen it.

function findRawTex(texts) {
  const commands = 'frac|dfrac|tfrac|int|iint|oint|sum|prod|sqrt|mathbf|mathrm|mathcal|mathbb|boldsymbol|operatorname|text|left|right|cdot|times|le|leq|ge|geq|ne|neq|approx|infty|partial|nabla|alpha|beta|gamma|delta|epsilon|varepsilon|eta|theta|lambda|mu|nu|pi|rho|sigma|tau|phi|varphi|omega|Omega|Phi|Theta|Lambda|Delta|Sigma|cos|sin|tan|arccos|arcsin|arctan|exp|log|ln|max|min|lim|hat|bar|vec|tilde|overline|quad|qquad|mathop|begin|end';
  const patterns = [
    /\$\$/,
    /\\begin\{|\\end\{/,
    new RegExp(`\\\\(?:${commands})(?![A-Za-z])`),
    /\$[^$\n]*\\[A-Za-z]+[^$\n]*\$/,
    /\\\(|\\\)|\\\[|\\\]/,
  ];
  const found = new Set();
  for (const t of texts) {
    if (!t || (!t.includes('\\') && !t.includes('$$'))) continue;
    for (const re of patterns) {
      const m = re.exec(t);
      if (m) {
        const at = Math.max(0, m.index - 30);
        found.add(short(t.slice(at, m.index + m[0].length + 30).trim(), 90));
        break;
      }
    }
  }
  return [...found];
}
