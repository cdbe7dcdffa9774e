"""Jupyter display of rendered files: a PDF shown inline
carries a PNG of the same figure beside it (a PDF alone is a blank box in
Chromium), through `_repr_mimebundle_`, which IPython asks first; the
PNG is the one `render(format="png")` gives."""

import jacobs_ladder as jl

PNG = b"\x89PNG\r\n\x1a\n"


def test_a_pdf_figure_displays_with_a_png_beside_it():
    scene = jl.Scene.builtin("2c")
    pdf = scene.render(format="pdf")
    assert isinstance(pdf, jl.Image) and pdf.format == "pdf"
    bundle = pdf._repr_mimebundle_()
    assert bundle["application/pdf"] == bytes(pdf)
    assert bundle["image/png"].startswith(PNG)
    assert bundle["image/png"] == bytes(scene.render(format="png"))
    # The HTML a browser shows is that PNG, not an embedded PDF.
    html = bundle["text/html"]
    assert "data:image/png;base64," in html and "<embed" not in html
    assert pdf._repr_png_() == bundle["image/png"]


def test_pdf_and_png_together_and_several_files_show_pngs():
    files = jl.Scene.builtin("2c").render(format="pdf,svg")
    pdf = next(v for k, v in files.items() if k.endswith(".pdf"))
    assert pdf._repr_mimebundle_()["image/png"].startswith(PNG)
    html = files._repr_html_()
    assert "data:image/png;base64," in html and "<embed" not in html


def test_other_formats_keep_their_own_display():
    png = jl.Scene.builtin("2c").render(format="png")
    assert png._repr_mimebundle_() is None
    assert png._repr_png_() == bytes(png)
    # An image made from bytes alone (no scene to draw a PNG from) keeps
    # the embedded PDF.
    bare = jl.Image(b"%PDF-1.7 ...", "x.pdf")
    assert "image/png" not in bare._repr_mimebundle_()
    assert "<embed" in bare._repr_html_()
