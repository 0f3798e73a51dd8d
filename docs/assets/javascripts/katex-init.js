// Typesets the equations of the page with the vendored KaTeX (no network).
// pymdownx.arithmatex (generic mode) and the docstring hook write inline math as
// <span class="arithmatex">\( ... \)</span> and display math as <div class="arithmatex">\[ ... \]</div>.
(function () {
  "use strict";

  function typeset(root) {
    var nodes = root.querySelectorAll(".arithmatex");
    for (var i = 0; i < nodes.length; i++) {
      var node = nodes[i];
      if (node.getAttribute("data-katex") === "done") {
        continue;
      }
      var display = node.tagName === "DIV";
      var tex = node.textContent.trim();
      // strip the delimiters arithmatex wrapped the TeX in
      var match = tex.match(/^\\\(([\s\S]*)\\\)$/) || tex.match(/^\\\[([\s\S]*)\\\]$/);
      if (match) {
        tex = match[1];
      }
      try {
        window.katex.render(tex, node, { displayMode: display, throwOnError: false });
        node.setAttribute("data-katex", "done");
      } catch (err) {
        node.setAttribute("data-katex", "error");
      }
    }
  }

  function run() {
    if (window.katex) {
      typeset(document.body);
    }
  }

  // Material's instant navigation swaps pages without a reload: it emits on document$.
  if (typeof window.document$ !== "undefined" && window.document$.subscribe) {
    window.document$.subscribe(run);
  } else if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", run);
  } else {
    run();
  }
})();
