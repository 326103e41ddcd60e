"""The lessons' diagrams (matplotlib) and the strips that set raylab renders side by side.

Usage: diagrams.py NAME OUT.png                      a diagram of DIAGRAMS
       diagrams.py strips OUT.png LABEL IN.png ...   the middle strip of each render, left to right
       diagrams.py palette IN.png OUT.png            a render as a small 256-colour PNG
make.sh calls it for every picture; all are 480 x 270 and at most 100 kB.
"""
import io
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches as mp  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from PIL import Image, ImageDraw, ImageFont  # noqa: E402

W, H, DPI = 480, 270, 100   # figure size in pixels at DPI; diagrams are saved at SCALE × DPI for print
SCALE = 2
BLUE, ORANGE, GREEN, GREY, RED = "#2a6bb3", "#d9822b", "#3a9a4a", "#777777", "#c0392b"
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"


def save_palette(image, out):
    """256 colours and PNG's best compression keep a picture small enough to commit."""
    image.convert("RGB").quantize(256, method=Image.Quantize.MEDIANCUT).save(out, optimize=True)


def figure():
    fig = plt.figure(figsize=(W / DPI, H / DPI), dpi=DPI)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_aspect("equal")
    ax.axis("off")
    return fig, ax


def finish(fig, out):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=DPI * SCALE, facecolor="white")
    plt.close(fig)
    buf.seek(0)
    save_palette(Image.open(buf), out)


def arrow(ax, start, end, colour, label=None, at=1.08, **text):
    ax.annotate("", xy=end, xytext=start, arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.6, mutation_scale=12))
    if label:
        x = start[0] + (end[0] - start[0]) * at
        y = start[1] + (end[1] - start[1]) * at
        ax.text(x, y, label, color=colour, ha="center", va="center", fontsize=11, **text)


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def rendering_equation(out):
    """Lesson 1: outgoing radiance gathers incoming radiance over the hemisphere, weighted by fr and cos."""
    fig, ax = figure()
    ax.set_xlim(-2.4, 2.4)
    ax.set_ylim(-0.45, 2.25)
    ax.add_patch(mp.Rectangle((-2.4, -0.45), 4.8, 0.45, color="#dddddd"))
    ax.add_patch(mp.Arc((0, 0), 2.6, 2.6, theta1=0, theta2=180, color=GREY, ls="--"))
    x = np.array([0.0, 0.0])
    arrow(ax, x, (0, 1.55), "black", "n", at=1.08)
    wi = unit((-1.0, 1.2)) * 1.3
    wo = unit((1.3, 0.9)) * 1.3
    arrow(ax, x, wi, ORANGE, r"$\omega_i$", at=1.15)
    arrow(ax, x, wo, BLUE, r"$\omega_o$", at=1.15)
    ax.add_patch(mp.Arc((0, 0), 0.9, 0.9, theta1=90, theta2=np.degrees(np.arctan2(wi[1], wi[0])), color=ORANGE))
    ax.text(-0.2, 0.62, r"$\theta_i$", color=ORANGE, fontsize=10)
    ax.plot(*x, "ko", ms=4)
    ax.text(0.08, -0.25, "x", fontsize=11)
    ax.text(-1.55, 1.45, r"$\Omega$: every $\omega_i$", color=GREY, fontsize=9)
    ax.text(0, 2.05, r"$L_o(x,\omega_o) = L_e(x,\omega_o) + \int_\Omega f_r(x,\omega_i,\omega_o)\,L_i(x,\omega_i)\,\cos\theta_i\,d\omega_i$",
            ha="center", fontsize=10.5)
    ax.text(1.45, 0.45, "to the camera", color=BLUE, fontsize=9)
    finish(fig, out)


def ray_sphere(out):
    """Lesson 3: the two roots, the normal, and the distance from the centre to the line."""
    fig, ax = figure()
    ax.set_xlim(-3.6, 2.6)
    ax.set_ylim(-1.75, 2.05)
    c, r = np.array([0.0, 0.35]), 1.0
    ax.add_patch(mp.Circle(c, r, fc="#e8f0fa", ec=BLUE, lw=1.5))
    o, d = np.array([-3.3, -1.3]), unit((1.0, 0.3))
    f = o - c
    b = -f @ d
    q = c - (o + b * d)                      # from the line's closest point to the centre
    h = np.sqrt(r * r - q @ q)
    t0, t1 = b - h, b + h
    p0, p1 = o + t0 * d, o + t1 * d
    ax.plot(*np.c_[o, o + (t1 + 0.9) * d], color="black", lw=1)
    arrow(ax, o, o + 0.8 * d, "black", "d", at=0.55, )
    ax.plot(*o, "ko", ms=4)
    ax.text(o[0] - 0.1, o[1] - 0.3, "o", fontsize=11)
    for p, name in ((p0, r"$t_0$"), (p1, r"$t_1$")):
        ax.plot(*p, "o", color=RED, ms=5)
        ax.text(p[0] - 0.05, p[1] - 0.3, name, color=RED, fontsize=11)
    arrow(ax, p0, p0 + 0.75 * (p0 - c) / r, GREEN)
    ax.text(*(p0 + 0.8 * (p0 - c) / r + np.array([-1.2, -0.35])), r"$n = (p-c)/R$", color=GREEN, fontsize=10)
    ax.plot(*c, "o", color=BLUE, ms=4)
    ax.text(c[0] + 0.07, c[1] + 0.07, "c", color=BLUE, fontsize=11)
    top = c + np.array([0.0, r])
    ax.plot(*np.c_[c, top], color=BLUE, lw=1)
    ax.text(c[0] - 0.22, c[1] + 0.5, "R", color=BLUE, fontsize=11)
    foot = o + b * d
    ax.plot(*np.c_[c, foot], color=ORANGE, ls="--", lw=1.2)
    ax.text((c[0] + foot[0]) / 2 + 0.1, (c[1] + foot[1]) / 2 - 0.05, r"$|c-(o+b'd)|$", color=ORANGE, fontsize=9)
    ax.text(-3.45, 1.72, r"$|o + t\,d - c|^2 = R^2$: two roots $t_0 \leq t_1$", fontsize=10.5)
    ax.text(-3.45, 1.38, r"$b'^2 - a c' = R^2 - |c-(o+b'd)|^2$ (Haines et al.)", fontsize=9, color=ORANGE)
    finish(fig, out)


def slab_test(out):
    """Lesson 5: the ray's interval inside each slab; it hits the box where the intervals overlap."""
    fig, ax = figure()
    ax.set_xlim(-0.3, 5.0)
    ax.set_ylim(-0.35, 2.65)
    x0, x1, y0, y1 = 1.8, 3.6, 0.9, 1.9
    ax.add_patch(mp.Rectangle((x0, -0.35), x1 - x0, 2.25, color="#dbe8f7"))
    ax.add_patch(mp.Rectangle((-0.3, y0), 5.3, y1 - y0, color="#fbe7d2", alpha=0.8))
    ax.add_patch(mp.Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, ec="black", lw=1.6))
    o, d = np.array([0.1, 0.1]), np.array([1.0, 0.32])
    tx = sorted(((x0 - o[0]) / d[0], (x1 - o[0]) / d[0]))
    ty = sorted(((y0 - o[1]) / d[1], (y1 - o[1]) / d[1]))
    near, far = max(tx[0], ty[0]), min(tx[1], ty[1])
    end = o + 4.8 * d
    ax.plot(*np.c_[o, end], color="black", lw=1)
    ax.plot(*np.c_[o + near * d, o + far * d], color=RED, lw=4, solid_capstyle="butt")
    ax.plot(*o, "ko", ms=4)
    ax.text(o[0] - 0.05, o[1] - 0.3, "o", fontsize=11)
    for t, name, colour, dy in ((tx[0], r"$t_{x0}$", BLUE, 0.25), (tx[1], r"$t_{x1}$", BLUE, 0.25),
                                (ty[0], r"$t_{y0}$", ORANGE, -0.35), (ty[1], r"$t_{y1}$", ORANGE, -0.35)):
        p = o + t * d
        ax.plot(*p, "o", color=colour, ms=5)
        ax.text(p[0] - 0.28 if dy > 0 else p[0] + 0.08, p[1] + dy * 0.6, name, color=colour, fontsize=11)
    ax.text(x0 + 0.05, -0.28, "x slab", color=BLUE, fontsize=9)
    ax.text(4.2, y1 - 0.25, "y slab", color=ORANGE, fontsize=9)
    ax.text(0.0, 2.42, r"$t_{near} = \max(t_{x0}, t_{y0})$,  $t_{far} = \min(t_{x1}, t_{y1})$", fontsize=10)
    ax.text(0.0, 2.12, r"hit when $t_{near} \leq t_{far}$ (and $t_{far} > 0$)", fontsize=10, color=RED)
    finish(fig, out)


def hemisphere_pdf(out):
    """Lesson 7: the uniform and the cosine pdf over the hemisphere, and cosine samples seen from above."""
    fig = plt.figure(figsize=(W / DPI, H / DPI), dpi=DPI)
    ax = fig.add_axes([0.02, 0.1, 0.55, 0.8])
    ax.set_aspect("equal")
    ax.axis("off")
    theta = np.linspace(-np.pi / 2, np.pi / 2, 200)
    for pdf, colour, name in ((np.full_like(theta, 1 / (2 * np.pi)), ORANGE, r"uniform $1/2\pi$"),
                              (np.cos(theta) / np.pi, BLUE, r"cosine $\cos\theta/\pi$")):
        ax.plot(pdf * np.sin(theta), pdf * np.cos(theta), color=colour, lw=2, label=name)
    ax.plot([-0.36, 0.36], [0, 0], color="black", lw=1.2)
    arrow(ax, (0, 0), (0, 0.36), "black", "n", at=1.08)
    ax.set_xlim(-0.37, 0.37)
    ax.set_ylim(-0.03, 0.4)
    ax.legend(loc="upper left", fontsize=8, frameon=False, bbox_to_anchor=(-0.02, 1.12))
    ax.text(0.0, -0.065, r"$p(\omega)$ drawn as a distance along $\omega$", ha="center", fontsize=8, color=GREY)
    bx = fig.add_axes([0.6, 0.14, 0.38, 0.68])
    bx.set_aspect("equal")
    bx.axis("off")
    rng = np.random.default_rng(7)
    u1, u2 = rng.random(400), rng.random(400)
    r, phi = np.sqrt(u1), 2 * np.pi * u2          # uniform on the disk, lifted: cosine on the hemisphere (Malley)
    bx.add_patch(mp.Circle((0, 0), 1, fill=False, ec=GREY))
    bx.plot(r * np.cos(phi), r * np.sin(phi), ".", color=BLUE, ms=2.5)
    bx.set_title("cosine samples from above:\nuniform on the disk", fontsize=8.5)
    finish(fig, out)


def microfacet_normal(out):
    """Lesson 8: only facets whose normal m equals the half vector h mirror wi into wo."""
    fig, ax = figure()
    ax.set_xlim(-2.4, 2.4)
    ax.set_ylim(-0.6, 2.1)
    rng = np.random.default_rng(3)
    xs = np.linspace(-2.4, 2.4, 17)
    ys = rng.normal(0, 0.12, xs.size) - 0.2
    wi, wo = unit((-1.0, 1.1)), unit((1.4, 0.7))
    h = unit(wi + wo)
    for a, b, ya, yb in zip(xs[:-1], xs[1:], ys[:-1], ys[1:]):
        m = unit((-(yb - ya), b - a))
        good = np.degrees(np.arccos(np.clip(m @ h, -1, 1))) < 12
        ax.plot([a, b], [ya, yb], color=ORANGE if good else "black", lw=3 if good else 1.2)
        if good:
            mid = np.array([(a + b) / 2, (ya + yb) / 2])
            arrow(ax, mid, mid + 0.45 * m, ORANGE, "m", at=1.25)
    ax.fill_between(xs, ys, -0.6, color="#eeeeee")
    x = np.array([0.0, 0.5])
    arrow(ax, x, x + 0.8 * wi, ORANGE, r"$\omega_i$", at=1.2)
    arrow(ax, x, x + 0.8 * wo, BLUE, r"$\omega_o$", at=1.2)
    arrow(ax, x, x + 0.8 * h, RED, "h", at=1.15)
    arrow(ax, (-2.0, 0.1), (-2.0, 0.8), "black", "n", at=1.15)
    ax.text(-2.3, 1.9, r"$h = (\omega_i + \omega_o)\,/\,|\omega_i + \omega_o|$", fontsize=10, color=RED)
    ax.text(-2.3, 1.62, r"facets with $m = h$ (orange) mirror $\omega_i$ into $\omega_o$; $D(h)$ counts them", fontsize=9.5)
    finish(fig, out)


def thin_lens(out):
    """Lesson 10: rays through the whole aperture meet on the focal plane and spread elsewhere."""
    fig, ax = figure()
    ax.set_xlim(-1.4, 6.2)
    ax.set_ylim(-2.1, 2.4)
    ax.add_patch(mp.Ellipse((0, 0), 0.25, 2.2, fc="#dbe8f7", ec=BLUE))
    ax.plot([-1.3, 6.1], [0, 0], color=GREY, lw=0.8, ls=":")
    ax.plot([-1.0, -1.0], [-1.0, 1.0], color="black", lw=2)
    ax.text(-1.35, -1.35, "image", fontsize=9)
    focus = 5.0
    ax.plot([focus, focus], [-1.6, 1.6], color=GREEN, lw=1.2, ls="--")
    ax.text(focus - 0.6, 1.75, "focal plane", color=GREEN, fontsize=9)
    f = np.array([focus, 0.7])
    pixel = np.array([-1.0, -0.7 / focus])
    for y in np.linspace(-1.0, 1.0, 5):
        lens = np.array([0.0, y])
        ax.plot(*np.c_[pixel, lens], color=ORANGE, lw=0.8)
        ax.plot(*np.c_[lens, f], color=ORANGE, lw=1)
    ax.plot(*f, "o", color=GREEN, ms=5)
    ax.text(f[0] + 0.12, f[1], "sharp", color=GREEN, fontsize=9)
    near = 2.3
    lo, hi = -1.0 + (f[1] + 1.0) * near / focus, 1.0 + (f[1] - 1.0) * near / focus
    ax.plot([near, near], [lo, hi], color=RED, lw=3)
    ax.text(near - 0.9, hi + 0.12, "circle of confusion", color=RED, fontsize=9)
    ax.annotate("", xy=(0, -1.25), xytext=(0, 1.25), arrowprops=dict(arrowstyle="<->", color=BLUE))
    ax.text(0.15, 1.3, "aperture", color=BLUE, fontsize=9)
    ax.annotate("", xy=(focus, -1.75), xytext=(0, -1.75), arrowprops=dict(arrowstyle="<->", color=GREEN))
    ax.text(1.9, -2.05, "focus distance", color=GREEN, fontsize=9)
    ax.text(-1.3, 2.1, "every lens sample aims at the same point of the focal plane", fontsize=9.5)
    finish(fig, out)


def plot(xlabel, ylabel):
    """A figure with plain axes, for the diagrams that are graphs."""
    fig = plt.figure(figsize=(W / DPI, H / DPI), dpi=DPI)
    ax = fig.add_axes([0.11, 0.17, 0.86, 0.78])
    ax.set_xlabel(xlabel, fontsize=9)
    ax.set_ylabel(ylabel, fontsize=9)
    ax.tick_params(labelsize=8)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    return fig, ax


def tone_curves(out):
    """Lesson 16: clamp, Reinhard and the ACES fit of shaders/include/tone_map.glsl over five decades."""
    fig, ax = plot(r"linear value $\times\ 2^{exposure}$", "display value before sRGB")
    x = np.logspace(-2, 2, 400)
    aces = np.clip(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
    ax.semilogx(x, np.minimum(x, 1), color=GREY, lw=2, label="clamp: min(x, 1)")
    ax.semilogx(x, x / (1 + x), color=BLUE, lw=2, label="Reinhard: x/(1 + x)")
    ax.semilogx(x, aces, color=ORANGE, lw=2, label="ACES fit (Narkowicz 2015)")
    ax.axvline(0.18, color=GREEN, lw=1, ls="--")
    ax.text(0.2, 0.03, "middle grey 0.18", color=GREEN, fontsize=8)
    ax.set_ylim(0, 1.05)
    ax.set_xlim(0.01, 100)
    ax.legend(loc="lower right", fontsize=8, frameon=False)
    finish(fig, out)


def schlick_angle(out):
    """Lesson 18: Schlick's F in the mirror configuration from the right cosine, ωi·h, and the thesis's ωi·ωo."""
    fig, ax = plot("angle θ of ωi and ωo from the normal (mirror configuration, h = n)", "Fresnel F, F0 = 0.04")
    theta = np.linspace(0, 90, 400)
    f0 = 0.04

    def schlick(c):
        return f0 + (1 - f0) * (1 - c) ** 5

    ax.plot(theta, schlick(np.cos(np.radians(theta))), color=BLUE, lw=2, label=r"right: cos = $\omega_i \cdot h$ = cos θ")
    ax.plot(theta, schlick(np.maximum(np.cos(np.radians(2 * theta)), 0)), color=RED, lw=2,
            label=r"slip: cos = $\omega_i \cdot \omega_o$ = cos 2θ")
    for f, colour in ((schlick(np.cos(np.radians(45))), BLUE), (1.0, RED)):
        ax.plot(45, f, "o", color=colour, ms=5)
        ax.text(46.5, f - 0.02 if f > 0.5 else f + 0.07, f"F = {f:.3f} at 45°", color=colour, fontsize=8,
                va="top" if f > 0.5 else "bottom")
    ax.set_xlim(0, 90)
    ax.set_ylim(0, 1.05)
    ax.set_xticks([0, 15, 30, 45, 60, 75, 90])
    ax.legend(loc="upper left", fontsize=8, frameon=False)
    finish(fig, out)


def strata(out):
    """Lesson 17: 16 independent points clump and leave cells empty; 16 stratified points fill each cell once."""
    fig = plt.figure(figsize=(W / DPI, H / DPI), dpi=DPI)
    rng = np.random.default_rng(19)
    cells = np.arange(16)
    jittered = (np.c_[cells % 4, cells // 4] + rng.random((16, 2))) / 4
    for left, points, title, colour in ((0.06, rng.random((16, 2)), "independent: clumps and holes", ORANGE),
                                        (0.54, jittered, "stratified: one point per cell", BLUE)):
        ax = fig.add_axes([left, 0.05, 0.4, 0.78])
        ax.set_aspect("equal")
        ax.set_xticks(np.linspace(0, 1, 5))
        ax.set_yticks(np.linspace(0, 1, 5))
        ax.set_xticklabels([])
        ax.set_yticklabels([])
        ax.tick_params(length=0)
        ax.grid(color="#cccccc", lw=0.8)
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.plot(points[:, 0], points[:, 1], "o", color=colour, ms=5)
        ax.set_title(title, fontsize=9.5, color=colour)
    finish(fig, out)


DIAGRAMS = {
    "rendering-equation": rendering_equation,
    "ray-sphere": ray_sphere,
    "slab-test": slab_test,
    "hemisphere-pdf": hemisphere_pdf,
    "microfacet-normal": microfacet_normal,
    "thin-lens": thin_lens,
    "tone-curves": tone_curves,
    "strata": strata,
    "schlick-angle": schlick_angle,
}


def strips(out, pairs):
    """The middle 1/n of each render, side by side, each labelled at its top."""
    images = [np.asarray(Image.open(path).convert("RGB")) for _, path in pairs]
    n, width = len(images), images[0].shape[1]
    w = width // n
    left = (width - w) // 2
    joined = np.concatenate([im[:, left:left + w] for im in images], axis=1)
    image = Image.fromarray(joined)
    draw = ImageDraw.Draw(image)
    font = ImageFont.truetype(FONT, 13)
    for i, (label, _) in enumerate(pairs):
        draw.text((i * w + 6, 5), label, fill="white", font=font, stroke_width=2, stroke_fill="black")
        if i:
            draw.line([(i * w, 0), (i * w, image.height)], fill="white", width=1)
    save_palette(image, out)


def main(args):
    if args[:1] == ["strips"] and len(args) >= 4 and len(args) % 2 == 0:
        strips(args[1], list(zip(args[2::2], args[3::2])))
    elif args[:1] == ["palette"] and len(args) == 3:
        save_palette(Image.open(args[1]), args[2])
    elif len(args) == 2 and args[0] in DIAGRAMS:
        DIAGRAMS[args[0]](args[1])
    else:
        sys.exit(__doc__ + "diagrams: " + ", ".join(DIAGRAMS))


if __name__ == "__main__":
    main(sys.argv[1:])
