"""A math renderer that needs no network: math is shown as its source text, set in code type.

Sphinx's default renderer, MathJax, loads its script from a CDN, and the site must open offline
(like the study's report.html). The pages write their formulas as plain text; this renderer keeps
any ``:math:`` role or directive readable without a script.
"""

from docutils import nodes


def _inline(self, node):
    self.body.append(f'<code class="math">{self.encode(node.astext())}</code>')
    raise nodes.SkipNode


def _block(self, node):
    self.body.append(f'<pre class="math">{self.encode(node.astext())}</pre>\n')
    raise nodes.SkipNode


def setup(app):
    app.add_html_math_renderer("plain", (_inline, None), (_block, None))
    return {"parallel_read_safe": True, "parallel_write_safe": True}
