"""The plot rules' drawings that the book's pages used to draw themselves."""

from __future__ import annotations

import pytest


@pytest.mark.heavy
def test_figure2s_diagram_names_the_hidden_units_and_draws_the_same_png(tmp_path):
    """Figure 2's diagram (rule ``figure2_architecture``): a PNG, the same for the same config;
    the hidden layer's size is the config's."""
    from PIL import Image

    from icub_affordance.figures import figure2_architecture

    paths = [tmp_path / "a.png", tmp_path / "b.png", tmp_path / "c.png"]
    for path, hidden in zip(paths, (10, 10, 40), strict=True):
        figure2_architecture(hidden, path)
    assert paths[0].read_bytes() == paths[1].read_bytes() != paths[2].read_bytes()
    assert Image.open(paths[0]).size[0] > 600


def test_save_records_the_smallest_drawn_text_and_the_dpi(tmp_path):
    """`save` writes the smallest text the figure draws (not hidden axes' nor empty strings) and
    its dpi into the PNG, for the book's test of each figure's text size at the page's width."""
    import matplotlib.pyplot as plt
    from PIL import Image

    from icub_affordance.figures import DPI_KEY, SMALLEST_FONT_KEY, save

    fig, ax = plt.subplots(figsize=(2, 1.5))
    ax.plot([0, 1])
    ax.tick_params(labelsize=7.5)
    ax.set_title("a title", fontsize=12)
    ax.text(0.5, 0.5, "", fontsize=2)
    hidden = fig.add_axes((0, 0, 0.1, 0.1))
    hidden.tick_params(labelsize=3)
    hidden.axis("off")
    save(fig, tmp_path / "tiny.png", dpi=90)
    with Image.open(tmp_path / "tiny.png") as image:
        assert image.text[SMALLEST_FONT_KEY] == "7.5" and image.text[DPI_KEY] == "90"
