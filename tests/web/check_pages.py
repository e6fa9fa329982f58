"""The web report read in a real browser (docs/web.md): every page of each folder given is
opened in headless Chromium, and the test fails where

- raw TeX shows in the rendered text (a backslash command or a $...$ outside the typeset
  formulas), or a rendering error is on the page (KaTeX's .katex-error, LaTeXML's .ltx_ERROR);
- an internal link or anchor does not resolve (a page, an id on it, a file beside the pages),
  an image does not load, or a link leaves the folder for the network;
- a page cannot be read: an empty body, a style sheet missing or empty.

With --screenshot PAGE PNG it also takes a picture of one page (for docs/).

With --expect PAGE#ANCHOR (repeated), each such address must be on its page: the lasting
addresses docs/web.md promises.

Each check's item must hold its proof in a <details> element, typeset: a formula, and no
program text (v_M^2, M*m, sqrt(...)) outside the formulas.

With --summary INDEX JSON (repeated), the verification summary of INDEX must give each
derivation's checks by status as JSON (derivations.json) holds them, each row adding up and
the last row the sum.

Usage: check_pages.py [--screenshot PAGE PNG] [--expect PAGE#ANCHOR]... [--summary INDEX JSON]... FOLDER...
       check_pages.py --self-test PAGE   (each fault, put in a copy of PAGE, must be reported)
Run by CTest as test_web, with the Chromium of Debian's package `chromium`.
"""
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import urllib.parse

HARNESS = r"""<!DOCTYPE html><html><head><meta charset="utf-8"></head><body>
<pre id="results">running</pre>
<script>
const pages = PAGES;
const expected = EXPECTED;
function load(url) {
  return new Promise(resolve => {
    const frame = document.createElement('iframe');
    frame.style.width = '1100px';
    frame.style.height = '900px';
    frame.onload = () => resolve(frame);
    frame.src = url;
    document.body.appendChild(frame);
  });
}
function texShown(doc) {
  // Text a reader sees: outside each formula's MathML (hidden, for screen readers) and its
  // TeX annotation.
  const found = [];
  const walker = doc.createTreeWalker(doc.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const hidden = node.parentElement.closest('.katex-mathml, annotation, script, style');
    if (hidden) continue;
    const text = node.textContent;
    const m = text.match(/\\[A-Za-z]+|\\[{}$_^&%#]|\$[^$\s][^$]*\$/);
    if (m) found.push(m[0] + ' in "' + text.trim().slice(0, 80) + '"');
  }
  return found;
}
(async () => {
  const problems = [];
  const files = [];
  const docs = {};
  for (const page of pages) docs[page] = (await load(page)).contentDocument;
  for (const page of pages) {
    const doc = docs[page];
    const say = what => problems.push(page + ': ' + what);
    if (!doc || !doc.body || doc.body.innerText.trim().length < 100) { say('an empty page'); continue; }
    const sheets = doc.querySelectorAll('link[rel=stylesheet]');
    if (sheets.length < 2) say('fewer style sheets than KaTeX\'s and Impact\'s');
    for (const link of sheets) {
      if (!link.sheet) { say('the style sheet ' + link.getAttribute('href') + ' did not load'); continue; }
      let rules = 0;
      try { rules = link.sheet.cssRules.length; } catch (e) { say('the style sheet ' + link.getAttribute('href') + ' cannot be read'); }
      if (rules === 0) say('the style sheet ' + link.getAttribute('href') + ' is empty');
    }
    for (const t of texShown(doc)) say('raw TeX shows: ' + t);
    for (const e of doc.querySelectorAll('.katex-error, .ltx_ERROR')) say('a rendering error: ' + e.textContent.slice(0, 80));
    if (doc.querySelectorAll('.katex').length === 0) say('no typeset formula');
    // Each check's proof, one click away and typeset: a <details> in its item, with a typeset
    // formula, and no program text (v_M^2, M*m, sqrt(...)) outside the formulas.
    for (const item of doc.querySelectorAll('li[id^="check-"]')) {
      const proof = item.querySelector(':scope > details.proof');
      if (!proof) { say('the check ' + item.id + ' has no proof to open'); continue; }
      if (!proof.querySelector('.katex')) say('the proof of ' + item.id + ' has no typeset formula');
      const walker = doc.createTreeWalker(proof, NodeFilter.SHOW_TEXT);
      for (let node = walker.nextNode(); node; node = walker.nextNode()) {
        if (node.parentElement.closest('.katex')) continue;
        const m = node.textContent.match(/[\w)]\^[\w(]|[\w)]\*[\w(]|sqrt\(/);
        if (m) say('program text in the proof of ' + item.id + ': "' + node.textContent.trim().slice(0, 80) + '"');
      }
    }
    for (const img of doc.images) if (!img.complete || img.naturalWidth === 0) say('the image ' + img.getAttribute('src') + ' did not load');
    for (const a of doc.querySelectorAll('a[href]')) {
      const href = a.getAttribute('href');
      const url = new URL(href, doc.URL);
      if (url.protocol !== 'file:') { say('a link off the folder: ' + href); continue; }
      const path = decodeURIComponent(url.pathname);
      if (path.endsWith('.html')) {
        const target = pages.find(p => decodeURIComponent(new URL(p).pathname) === path);
        if (!target) { say('a link to a page that is not there: ' + href); continue; }
        const id = decodeURIComponent(url.hash.slice(1));
        if (id && !docs[target].getElementById(id)) say('a link to an anchor that is not there: ' + href);
      } else {
        files.push([page, href, path]);
      }
    }
  }
  for (const [page, id] of expected)
    if (!docs[page] || !docs[page].getElementById(id)) problems.push(page + ': the address #' + id + ' is not there');
  document.getElementById('results').textContent = JSON.stringify({problems: problems, files: files, pages: pages.length});
})();
</script></body></html>
"""


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return shutil.which(name)
    sys.exit("check_pages.py: no Chromium (install Debian's package chromium: scripts/setup.sh)")


BROWSER_FLAGS = ["--headless=new", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
                 "--disable-extensions", "--mute-audio"]


def url_of(path):
    return "file://" + urllib.parse.quote(os.path.abspath(path))


def check(folders, expected=()):
    """The problems of the pages of `folders`; `expected` holds addresses (a page's path and
    an anchor on it) that must be there."""
    pages = []
    for folder in folders:
        for name in sorted(os.listdir(folder)):
            if name.endswith(".html"):
                pages.append(url_of(os.path.join(folder, name)))
    if not pages:
        return ["no page in " + ", ".join(folders)], 0
    with tempfile.TemporaryDirectory(prefix="impact-web-") as scratch:
        harness = os.path.join(scratch, "harness.html")
        with open(harness, "w") as f:
            f.write(HARNESS.replace("PAGES", json.dumps(pages)).replace(
                "EXPECTED", json.dumps([[url_of(page), anchor] for page, anchor in expected])))
        profile = os.path.join(scratch, "profile")
        run = subprocess.run([chromium(), *BROWSER_FLAGS, "--user-data-dir=" + profile,
                              "--allow-file-access-from-files", "--virtual-time-budget=120000", "--dump-dom",
                              "file://" + harness], capture_output=True, text=True, timeout=600)
    found = re.search(r'<pre id="results">(.*?)</pre>', run.stdout, re.S)
    if not found or found.group(1) == "running":
        return ["the pages could not be checked: Chromium gave no results (" + run.stderr.strip()[-300:] + ")"], 0
    results = json.loads(html.unescape(found.group(1)))
    problems = results["problems"]
    for page, href, path in results["files"]:
        if not os.path.isfile(path):
            problems.append(f"{page}: a link to a file that is not there: {href}")
    return problems, results["pages"]


def summary_problems(index, derivations_json):
    """The verification summary of `index` (index.html) against `derivations_json`: each
    derivation's checks by status and those Z3 confirmed, counted here from the JSON; each
    row's statuses add up to its checks, and the last row is the sum of the others."""
    with open(index) as f:
        page = f.read()
    with open(derivations_json) as f:
        derivations = json.load(f)["derivations"]
    at = page.find('id="verification"')
    if at < 0:
        return [f"{index}: no verification summary (#verification)"]
    table = page[at:page.find("</table>", at)]
    rows = []
    for row in re.findall(r"<tr>(.*?)</tr>", table, re.S)[1:]:
        cells = [re.sub(r"<[^>]+>", "", c) for c in re.findall(r"<td>(.*?)</td>", row, re.S)]
        rows.append((html.unescape(cells[0]), [int(c) for c in cells[1:]]))
    problems = []
    expected = []
    for d in derivations:
        statuses = [c["status"] for c in d["checks"]]
        counts = [len(statuses),
                  sum(s == "proven" for s in statuses),
                  sum(s.startswith("proven,") for s in statuses),
                  sum(s.startswith("sampled") for s in statuses),
                  sum(not s.startswith(("proven", "sampled")) for s in statuses),
                  sum(c.get("z3") == "confirmed" for c in d["checks"])]
        expected.append((d["title"], counts))
    if len(rows) != len(expected) + 1:
        return [f"{index}: the verification summary has {len(rows)} rows, not one per derivation "
                f"({len(expected)}) and the sum"]
    for (title, counts), (shown, numbers) in zip(expected, rows):
        if shown != title or numbers != counts:
            problems.append(f"{index}: the verification summary says {shown}: {numbers}; "
                            f"derivations.json says {title}: {counts}")
    for shown, numbers in rows:
        if numbers[0] != sum(numbers[1:5]):
            problems.append(f"{index}: the verification summary's row {shown} does not add up: {numbers}")
    # Every check's proof typeset, a page's or not (a check said with another is in no
    # item): no program text outside its formulas.
    for d in derivations:
        for c in d["checks"]:
            words = re.sub(r"\$[^$]*\$", "", c.get("proof_latex", ""))
            found = re.search(r"\\\^\{\}|[\w)]\*[\w(]|sqrt\(", words)
            if found:
                problems.append(f"{derivations_json}: program text in the proof of {d['id']}'s check {c['name']}: "
                                f"{words[max(0, found.start() - 40):found.end() + 40]!r}")
    total = [sum(n[i] for _, n in rows[:-1]) for i in range(6)]
    if rows[-1][1] != total:
        problems.append(f"{index}: the verification summary's last row {rows[-1][1]} is not the sum {total}")
    return problems


def screenshot(page, png):
    with tempfile.TemporaryDirectory(prefix="impact-web-") as scratch:
        subprocess.run([chromium(), *BROWSER_FLAGS, "--user-data-dir=" + os.path.join(scratch, "profile"),
                        "--window-size=1100,1400", "--screenshot=" + os.path.abspath(png),
                        "file://" + urllib.parse.quote(os.path.abspath(page))],
                       capture_output=True, text=True, timeout=300, check=True)
    if not os.path.isfile(png) or os.path.getsize(png) < 10000:
        sys.exit(f"check_pages.py: no screenshot of {page}")


def self_test(model):
    """The checker itself, on pages broken on purpose from `model` (a page of a folder with its
    katex/ and impact.css beside it): each fault must be reported."""
    folder = os.path.dirname(os.path.abspath(model))
    with open(model) as f:
        good = f.read()
    faults = {
        "raw_tex.html": (good.replace("<main>", "<main><p>The velocity \\frac{J}{M} and $v_M$ as source.</p>", 1),
                         "raw TeX shows: \\frac"),
        "dollars.html": (good.replace("<main>", "<main><p>Then $v_M = 1$ here.</p>", 1), "raw TeX shows: $v_M = 1$"),
        "katex_error.html": (good.replace("<main>", '<main><span class="katex-error">\\fra</span>', 1),
                             "a rendering error"),
        "anchor.html": (good.replace("<main>", '<main><a href="#no-such-result">x</a>', 1),
                        "a link to an anchor that is not there: #no-such-result"),
        "page.html": (good.replace("<main>", '<main><a href="no_such_page.html#x">x</a>', 1),
                      "a link to a page that is not there: no_such_page.html#x"),
        "file.html": (good.replace("<main>", '<main><a href="figures/none.svg">x</a>', 1),
                      "a link to a file that is not there: figures/none.svg"),
        "network.html": (good.replace("<main>", '<main><a href="https://example.org/">x</a>', 1),
                         "a link off the folder: https://example.org/"),
        "style.html": (good.replace('href="impact.css"', 'href="missing.css"'), "the style sheet missing.css"),
        "empty.html": (re.sub(r"<body>.*</body>", "<body></body>", good, flags=re.S), "an empty page"),
        "no_proof.html": (good.replace('<details class="proof">', '<details class="other">', 1),
                          "has no proof to open"),
        "program_text.html": (good.replace("<summary>Proof</summary>", "<summary>Proof</summary><p>How: M*m*(1-eps^2).</p>", 1),
                              "program text in the proof of"),
    }
    with tempfile.TemporaryDirectory(prefix="impact-web-faults-") as scratch:
        shutil.copytree(os.path.join(folder, "katex"), os.path.join(scratch, "katex"))
        shutil.copy(os.path.join(folder, "impact.css"), scratch)
        for name, (text, _) in faults.items():
            with open(os.path.join(scratch, name), "w") as f:
                f.write(text)
        problems, _ = check([scratch])
    missed = [f"{name}: not reported: {what}" for name, (_, what) in faults.items()
              if not any(f"/{name}: " in p and what in p for p in problems)]
    # The verification summary: a derivation's number of checks changed (it no longer matches
    # derivations.json, nor adds up), and the last row's count of Z3's confirmations changed
    # (it is no longer the sum).
    index = os.path.join(folder, "index.html")
    summary = os.path.join(os.path.dirname(folder), "derivations.json")
    total = 3
    if os.path.isfile(index) and os.path.isfile(summary):
        with open(index) as f:
            page = f.read()
        at = page.index('id="verification"')

        def bumped(cell):
            end = page.index("<", cell)
            return page[:cell] + str(int(page[cell:end]) + 1) + page[end:]

        first = page.index("</td><td>", page.index("<tr><td><a", at)) + 9
        last_row = page.index("<tr><td><strong>all</strong>", at)
        last = page.rindex("<td>", last_row, page.index("</tr>", last_row)) + 4
        summary_faults = {"checks changed": (bumped(first), ["derivations.json says", "does not add up"]),
                          "the sum changed": (bumped(last), ["is not the sum"])}
        for name, (text, whats) in summary_faults.items():
            with tempfile.TemporaryDirectory(prefix="impact-web-faults-") as scratch:
                wrong = os.path.join(scratch, "index.html")
                with open(wrong, "w") as f:
                    f.write(text)
                found = summary_problems(wrong, summary)
            for what in whats:
                if not any(what in p for p in found):
                    missed.append(f"index.html, {name}: not reported: {what}")
        # A proof in derivations.json with program text in its words.
        with open(summary) as f:
            data = json.load(f)
        data["derivations"][0]["checks"][0]["proof_latex"] = "Claim: $x > 0$.\n\nHow: M*m*(1-eps^2).\n\n"
        with tempfile.TemporaryDirectory(prefix="impact-web-faults-") as scratch:
            wrong = os.path.join(scratch, "derivations.json")
            with open(wrong, "w") as f:
                json.dump(data, f)
            if not any("program text in the proof of" in p for p in summary_problems(index, wrong)):
                missed.append("derivations.json: not reported: program text in a proof")
    else:
        missed.append(f"no index.html and derivations.json beside {folder} for the summary's faults")
    for m in missed:
        print(m)
    print(f"check_pages.py --self-test: {len(faults) + total - len(missed)} of {len(faults) + total} faults reported")
    return not missed


def main():
    args = sys.argv[1:]
    if args[:1] == ["--self-test"]:
        sys.exit(0 if self_test(args[1]) else 1)
    shot = None
    expected = []
    summaries = []
    while args[:1] in (["--screenshot"], ["--expect"], ["--summary"]):
        if args[0] == "--screenshot":
            shot, args = args[1:3], args[3:]
        elif args[0] == "--summary":
            summaries.append(args[1:3])
            args = args[3:]
        else:
            page, _, anchor = args[1].partition("#")
            expected.append((page, anchor))
            args = args[2:]
    problems, count = check(args, expected)
    for index, derivations in summaries:
        problems += summary_problems(index, derivations)
    for p in problems:
        print(p)
    print(f"check_pages.py: {count} pages read in Chromium, {len(problems)} problems")
    if shot:
        screenshot(*shot)
        print(f"check_pages.py: {shot[0]} pictured in {shot[1]}")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
