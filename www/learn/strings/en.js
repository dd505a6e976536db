// @ts-check
// The tour's text in English (learn.html), apart from its markup and code. Every language has a file
// like this one with the same keys (tests/js/learn-strings.test.mjs): `page`, each piece of the
// article by key (HTML: the markup, ids and links the same in every language, only the words
// translated), which scripts/pages.mjs writes into learn.html where www/learn/page.html has
// `{{key}}` (so the English is what the page shows with no script, and prints); `live`, the text
// page.js writes as the figures change; `canvas`, the words the module draws on the figures
// (`{name}` is a value the module fills in); `runtime`, the shared runtime's words on this page, by
// their English (www/runtime/dom.js `say`). www/learn/strings/index.js picks the language.

/** Each piece of the article, by its key in page.html. */
export const page = {
  "title": "Rotations, from a turn to the Kuramoto flow — a guided tour of kli",
  "description": "An explorable tour for students: rotations, quaternions, S³, SLERP, the Hopf map, the Kuramoto model and the KLI interpolation of Kapić and Crnkić, every idea with a live figure and an exercise.",
  "languages.aria": "Language",
  "header.h1": "Rotations, from a turn to the Kuramoto flow",
  "header.p1":
    `A guided tour for anyone who knows vectors and matrices and has never met a quaternion. It ends at the method of
    the paper <a href="#paper">“Interpolating Rotations with Non-abelian Kuramoto Model on the 3-Sphere”</a> by
    Zinaid Kapić and Aladin Crnkić, which this site implements. Every figure is live: move its slider and the text
    beside it quotes the new values. The figures that move in time share one time <var>t</var>, set by the time
    bar at the foot of the screen. Each section ends with a question: predict the answer, then press the button in it to check.`,
  "contents.item1": `<a href="#care">Why rotations need care</a>`,
  "contents.item2": `<a href="#turn">An axis, an angle, four numbers</a>`,
  "contents.item3": `<a href="#cover">S³ and the double cover</a>`,
  "contents.item4": `<a href="#slerp">SLERP: the great circle at constant speed</a>`,
  "contents.item5": `<a href="#hopf">The Hopf map, and the roll it cannot show</a>`,
  "contents.item6": `<a href="#kuramoto">Oscillators falling into step</a>`,
  "contents.item7": `<a href="#kli">KLI: the paper's flow</a>`,
  "contents.item8": `<a href="#integrators">Integrators and drift</a>`,
  "contents.item9": `<a href="#many">Many rotations</a>`,
  "contents.item10": `<a href="#glossary">Glossary</a> · <a href="#paper">References</a>`,
  "care.title1": `<span class="number">1</span> Why rotations need care`,
  "care.caption1":
    `The aircraft turned by the three angles, with the three axes the angles turn about: yaw (blue), pitch (green),
    bank (red, along the nose).`,
  "care.p1":
    `A rotation turns every vector about the origin, keeping lengths and angles. In a matrix course you met it as a 3
    × 3 <em>rotation matrix</em> <var>R</var>: its columns are where the three axes go, and
    <var>R</var>ᵀ<var>R</var> = <var>I</var>, det <var>R</var> = 1. That is nine numbers held together by six
    equations, for only three freedoms. Multiply a few thousand of them in floating point and rounding slowly breaks
    the equations; average two of them entry by entry and the result is no rotation at all: halfway between
    <var>I</var> and a half turn about <var>z</var> is diag(0, 0, 1), which flattens all of space onto the <var>z</var> axis (its determinant is 0).`,
  "care.p2":
    `Three numbers then? <dfn id="def-euler">Euler angles</dfn> turn about <var>z</var> by the yaw, then about the
    new <var>y</var> by the pitch, then about the new <var>x</var> (the nose) by the bank (pilots also call this
    angle the roll; this tour calls it bank, and keeps “roll” for the extra turn about the nose in section 5): <var>R</var> = <var>R<sub>z</sub></var>(yaw)
    <var>R<sub>y</sub></var>(pitch) <var>R<sub>x</sub></var>(bank). (Read right to left, as the matrices act on a
    vector, the same product turns about the world's fixed axes in the other order: bank about <var>x</var>, then pitch
    about <var>y</var>, then yaw about <var>z</var>. Both readings give the same <var>R</var>.) Move the pitch towards 90° below and watch the
    yaw axis and the bank axis close in on each other. At 90° they are one line: yaw and bank now do the same thing
    and one freedom is gone. That is <dfn id="def-gimbal">gimbal lock</dfn> (a gimbal is a set of nested rings, each turning about one
    axis, that holds a compass or a camera), and every choice of three angles runs into
    it somewhere.`,
  "care.legend1": "Euler angles",
  "care.p3":
    `Now the yaw axis and the bank axis are <output id="lock-out">50.0°</output> apart (the angle is 90° − |pitch|).`,
  "care.p4":
    `What we want instead: few numbers, one easy condition, no lock, a product for doing one turn after another, and
    a clean way to go <em>between</em> two rotations. Quaternions give all of that, which is why aircraft simulators
    and computer graphics took them up, as the paper recalls in its introduction.`,
  "exercise.answer": "Show the answer",
  "care.question1": "Predict, then check: at pitch 90°, what do yaw and bank do?",
  "care.p5":
    `Make your guess first. Then <a class="set" href="?pitch=90#care" data-state='{"pitch":90}'>set the pitch to
    90°</a> and move the yaw and the bank sliders in turn.`,
  "care.p6":
    `<strong>Answer.</strong> Both turn the aircraft about the same vertical line, and the text reads 0° apart. With
    the nose pointing straight down (pitch 90° turns <var>x</var> to −<var>z</var>; with <var>z</var> up, positive pitch here tips the nose
    down), the bank axis is the yaw axis,
    so the two angles only count together: what matters is yaw minus bank. No small change of the three angles turns
    the nose sideways.`,
  "turn.title1": `<span class="number">2</span> An axis, an angle, four numbers`,
  "turn.p1":
    `Euler showed that every rotation is a single turn by an angle <var>θ</var> about an axis, a unit vector
    <var>u</var>. A <dfn id="def-quaternion">quaternion</dfn> is a number <var>q</var> = <var>a</var> + <var>b</var>
    i + <var>c</var> j + <var>d</var> k with four real parts, where Hamilton's rules i² = j² = k² = ijk = −1 fix how
    to multiply. The order matters: ij = k, jk = i, ki = j, but ji = −k, kj = −i, ik = −j. Its length is |<var>q</var>| = √(<var>a</var>² +
    <var>b</var>² + <var>c</var>² + <var>d</var>²), its conjugate is <var>q̄</var> = <var>a</var> − <var>b</var> i −
    <var>c</var> j − <var>d</var> k, and a <dfn id="def-unit-quaternion">unit quaternion</dfn> is one of length 1.`,
  "turn.p2":
    `Products are quickest with vectors. Write a quaternion as a real part and a vector part, <var>a</var> +
    <var>m</var> with <var>m</var> = <var>b</var> i + <var>c</var> j + <var>d</var> k, reading i, j and k as the
    unit vectors along <var>x</var>, <var>y</var> and <var>z</var>. Real numbers commute with i, j and k, and
    the rules above give (<var>s</var> + <var>m</var>)(<var>t</var> + <var>n</var>) = (<var>s</var><var>t</var>
    − <var>m</var>·<var>n</var>) + (<var>s</var><var>n</var> + <var>t</var><var>m</var> + <var>m</var> ×
    <var>n</var>), with the dot and cross products of R³: multiply <var>m</var><var>n</var> out term by term,
    and the squares (i² = j² = k² = −1) give −<var>m</var>·<var>n</var> while the mixed products (ij = k, ji =
    −k, …) give <var>m</var> × <var>n</var> (try <var>m</var> = i, <var>n</var> = j: 0 + i × j = k). Like matrix
    products, these products are associative, (<var>p</var><var>q</var>)<var>r</var> =
    <var>p</var>(<var>q</var><var>r</var>), though not commutative. Three facts follow, and the tour uses them
    all the way through. First, <var>q</var><var>q̄</var> = <var>q̄</var><var>q</var> = |<var>q</var>|², so for
    a unit quaternion <var>q̄</var> undoes <var>q</var>. Second, the conjugate of a product is the product of
    the conjugates in the opposite order: <var>q̄</var><var>p̄</var> for <var>p</var><var>q</var>, because
    <var>m</var> × <var>n</var> = −<var>n</var> × <var>m</var>. Third, with <var>p</var> = <var>a</var> +
    <var>b</var> i + <var>c</var> j + <var>d</var> k and <var>r</var> = <var>a′</var> + <var>b′</var> i +
    <var>c′</var> j + <var>d′</var> k, the real part of <var>r</var><var>p̄</var> is <var>a</var><var>a′</var> +
    <var>b</var><var>b′</var> + <var>c</var><var>c′</var> + <var>d</var><var>d′</var>: the dot product of
    <var>p</var> and <var>r</var> read as vectors of R⁴, which section 3 writes <var>p</var>·<var>r</var>.`,
  "turn.p3": "The turn by <var>θ</var> about <var>u</var> is the unit quaternion",
  "turn.p4":
    `<var>q</var> = cos(<var>θ</var>/2) + sin(<var>θ</var>/2) (<var>u<sub>x</sub></var> i + <var>u<sub>y</sub></var>
    j + <var>u<sub>z</sub></var> k),`,
  "turn.p5":
    `and it turns a vector <var>v</var>, written as <var>v<sub>x</sub></var> i + <var>v<sub>y</sub></var> j +
    <var>v<sub>z</sub></var> k, into <var>q</var> <var>v</var> <var>q̄</var>. Try it on the figure's first turn, 90° about <var>z</var>:
    <var>q</var> = (1 + k)/√2 and <var>q̄</var> = (1 − k)/√2. Then <var>q</var> i = (i + ki)/√2 = (i + j)/√2, and
    (i + j)(1 − k)/2 = (i − ik + j − jk)/2 = (i + j + j − i)/2 = j: the nose, <var>x</var>, goes to <var>y</var>, a
    quarter turn. Look at the halfway point: <var>q</var> i = (i + j)/√2 is i already turned by 45° about
    <var>z</var>, and multiplying by <var>q̄</var> on the right turns it the other 45°. For a vector square to the
    axis, each factor turns it by <var>θ</var>/2, which is why <var>q</var> holds half the angle; a vector along the
    axis is left alone by the pair, though not by either factor alone: <var>q</var> k <var>q̄</var> = k. Every vector is a part along the axis plus a part square to it,
    and <var>v</var> ↦ <var>q</var> <var>v</var> <var>q̄</var> is linear, so the two cases settle every vector; and
    the result has no real part, since by the second fact its conjugate is <var>q</var> <var>v̄</var> <var>q̄</var> =
    −<var>q</var> <var>v</var> <var>q̄</var>, so it is a vector again. One turn after another is a product:
    <var>q</var>₂<var>q</var>₁ turns by <var>q</var>₁ first, since <var>q</var>₂(<var>q</var>₁ <var>v</var>
    <var>q̄</var>₁)<var>q̄</var>₂ = (<var>q</var>₂<var>q</var>₁) <var>v</var> (<var>q̄</var>₁<var>q̄</var>₂) by
    associativity, and <var>q̄</var>₁<var>q̄</var>₂ is the conjugate of <var>q</var>₂<var>q</var>₁ by the second fact. Four numbers and one condition, |<var>q</var>| = 1, and if rounding spoils it, dividing <var>q</var> by
    |<var>q</var>| restores it.`,
  "turn.caption1":
    `The aircraft turned by <var>q</var>. The dashed line is the turn's axis, fixed in the world. The coloured arrows
    are the aircraft's body axes, which turn with it: <span class="x">x</span> (the nose), <span class="y">y</span> (a
    wing), <span class="z">z</span> (the fin). Before the turn they lie along the world's <var>x</var>, <var>y</var> and
    <var>z</var>, so after it each shows where <var>q</var> sends that world axis.`,
  "turn.legend1": "The turn",
  "turn.p6":
    `The four numbers now: <output id="turn-out">q = 0.707 + 0.000 i + 0.000 j + 0.707 k</output>.`,
  "turn.question1":
    `Predict, then check: a turn by 120° about the diagonal (1, 1, 1)/√3. What are the four numbers, and where does
    the nose go?`,
  "turn.p7":
    `Work it out from the formula first. Then <a class="set" href="?axis=diagonal&amp;angle=120#turn"
    data-state='{"axis":"diagonal","angle":120}'>set 120° about the diagonal</a>.`,
  "turn.p8":
    `<strong>Answer.</strong> cos 60° = 0.5, sin 60° = 0.866, and each part of the axis is 1/√3 = 0.577, so each
    of i, j, k gets 0.866 × 0.577 = 0.5: <var>q</var> = 0.5 + 0.5 i + 0.5 j + 0.5 k, the rotation <var>r</var>
    of the paper's example, which we meet again in section 4. A third of a full turn about the diagonal takes the axes round in a cycle: the nose, the
    <var>x</var> axis, goes to <var>y</var> (<var>q</var> i <var>q̄</var> = j), <var>y</var> goes to <var>z</var>
    and <var>z</var> to <var>x</var>.`,
  "cover.title1": `<span class="number">3</span> S³ and the double cover`,
  "cover.p1":
    `The four numbers of a unit quaternion are a point at distance 1 from the origin of four-dimensional space: the
    unit quaternions form the <dfn id="def-s3">3-sphere, S³</dfn>, a three-dimensional surface in R⁴, as the
    ordinary sphere S² is a two-dimensional surface in R³. We cannot draw it whole, but we can draw one slice: as
    <var>θ</var> grows, <var>q</var> = cos(<var>θ</var>/2) + sin(<var>θ</var>/2) <var>u</var> runs round the circle
    through 1 and <var>u</var>, at half the speed of the turn.`,
  "cover.p2":
    `Press 360° below. The aircraft is back where it started, yet <var>q</var> = −1 is on the far side of the circle.
    Since (−<var>q</var>) <var>v</var> (−<var>q̄</var>) = <var>q</var> <var>v</var> <var>q̄</var>, the quaternions
    <var>q</var> and −<var>q</var> are one rotation: every rotation is a pair of opposite points of S³. This is the
    <dfn id="def-double-cover">double cover</dfn>, and a method on rotations must either ignore the sign or say which
    one it takes.`,
  "cover.p3":
    `Read each unit quaternion <var>a</var> + <var>b</var> i + <var>c</var> j + <var>d</var> k as the vector
    (<var>a</var>, <var>b</var>, <var>c</var>, <var>d</var>) of R⁴. For two of them, <var>p</var> and <var>r</var>,
    the angle <var>φ</var> between them is the usual one, from the dot product of the two four-vectors: cos
    <var>φ</var> = <var>p</var>·<var>r</var>. It measures how far apart the rotations are.`,
  "cover.p4":
    `How far, as a turn? The turn that takes <var>p</var> to <var>r</var> is <var>r</var> <var>p̄</var>, since
    (<var>r</var> <var>p̄</var>) <var>p</var> = <var>r</var> (<var>p̄</var> <var>p</var>) = <var>r</var>, and by
    section 2 its real part is <var>p</var>·<var>r</var> = cos <var>φ</var>. A real part cos(<var>θ</var>/2) is a turn by
    <var>θ</var> (section 2 again: a unit quaternion with real part cos(<var>θ</var>/2), <var>θ</var> from 0° to 360°, has a vector part of length
    sin(<var>θ</var>/2), since <var>a</var>² + |<var>m</var>|² = 1, so it is cos(<var>θ</var>/2) + sin(<var>θ</var>/2)
    <var>u</var> with <var>u</var> the unit vector along its vector part), so the rotation from <var>p</var> to <var>r</var> turns by 2<var>φ</var>: angles on S³ are half
    the angles of the turns. (When <var>p</var>·<var>r</var> &lt; 0, 2<var>φ</var> is more than 180°, and the same
    rotation is the turn by 360° − 2<var>φ</var> the other way.)`,
  "cover.p5":
    `The shortest way along the sphere is an arc of a great circle (where the sphere meets a plane through its
    centre), a <dfn id="def-geodesic">geodesic</dfn>. Between two rotations there are two such arcs, to
    <var>r</var> and to −<var>r</var>; “the shortest path” takes the one with <var>p</var>·<var>r</var> ≥ 0.
    <a href="#kli">KLI</a>, the paper's method (section 7), does not choose: from <var>p</var>·<var>r</var> &lt; 0
    it flows the long way round, so first flip <var>r</var> to make <var>p</var>·<var>r</var> ≥ 0.`,
  "cover.caption1":
    `Left (above, on a narrow screen): the circle of S³ through 1 and the axis <var>u</var>, the arc from 1 to
    <var>q</var>, and −<var>q</var> opposite. Right (below): the aircraft turned by <var>q</var> and by −<var>q</var>.`,
  "cover.p6":
    `At <output id="cover-out">θ = 90°, q = 0.707 + 0.000 i + 0.000 j + 0.707 k</output> (the angle slider of section
    2 moves it too).`,
  "cover.question1": "Predict, then check: how far must the aircraft turn before q is back at 1?",
  "cover.p7":
    `Guess, then <a class="set" href="?angle=720#cover" data-state='{"angle":720}'>set θ = 720°</a>.`,
  "cover.p8":
    `<strong>Answer.</strong> Two full turns. After one turn <var>q</var> = −1: the same rotation, the other point.
    Only at 720° has <var>q</var> gone once round its circle.`,
  "slerp.title1": `<span class="number">4</span> SLERP: the great circle at constant speed`,
  "slerp.p1":
    `To animate a turn from a rotation <var>p</var> to a rotation <var>r</var> we need a path
    <var>q</var>(<var>s</var>), <var>s</var> from 0 to 1. The straight line (1 − <var>s</var>)<var>p</var> +
    <var>s</var><var>r</var> cuts through the inside of the sphere; pushed back out (<abbr
    title="normalised linear interpolation">NLERP</abbr>, normalised linear interpolation: the straight line's point
    divided by its length), its points land on the right arc but unevenly, quicker in the middle. <dfn
    id="def-slerp">SLERP</dfn>, spherical linear interpolation (Shoemake, 1985), walks the great circle at constant
    speed:`,
  "slerp.p2":
    `<var>q</var>(<var>s</var>) = [sin((1 − <var>s</var>)<var>φ</var>₀) <var>p</var> + sin(<var>s</var><var>φ</var>₀)
    <var>r</var>] / sin <var>φ</var>₀, cos <var>φ</var>₀ = <var>p</var>·<var>r</var>.`,
  "slerp.p3":
    `Its point is <var>s</var><var>φ</var>₀ along the arc. Equivalently <var>q</var>(<var>s</var>) = <var>w</var>
    <var>p</var>, where <var>w</var> is the turn by 2<var>s</var><var>φ</var>₀ about the axis of <var>r</var>
    <var>p̄</var> (section 3's turn from <var>p</var> to <var>r</var>, by 2<var>φ</var>₀), done a fraction
    <var>s</var> at a time: so the object turns about that one fixed axis at a steady rate.
    Below are the paper's two rotations, <var>p</var> = k, a half turn about <var>z</var> (θ = 180°, since cos 90° +
    sin 90° k = k), and <var>r</var> = ½(1 + i + j + k), a third of a turn (120°) about the diagonal (1, 1, 1):
    <var>p</var>·<var>r</var> = ½, so <var>φ</var>₀ = 60° on S³, a 120° turn of the object. We meet them again in
    section 7.`,
  "slerp.caption1":
    `The arc from <var>p</var> to <var>r</var>; ticks every 0.1 of <var>s</var>, <span class="slerp">SLERP</span>'s
    outside, NLERP's inside; the chord, the straight segment from <var>p</var> to <var>r</var>, dashed.`,
  "slerp.legend1": "SLERP",
  "slerp.p4": `<output id="slerp-out">At s = 0.50 SLERP is 30.00° along the arc, NLERP 30.00°.</output>`,
  "slerp.question1": "Predict, then check: at s = 0.25, is NLERP ahead of SLERP or behind it?",
  "slerp.p5": `Guess, then <a class="set" href="?s=0.25#slerp" data-state='{"s":0.25}'>set s = 0.25</a>.`,
  "slerp.p6":
    `<strong>Answer.</strong> Behind: 13.90° against SLERP's 15°. The chord's point at a quarter of the way is (0.75
    + 0.25 cos 60°, 0.25 sin 60°) in the plane of the arc, at atan(0.2165 / 0.875) = 13.90°. By symmetry it is ahead
    after the middle (46.10° at <var>s</var> = 0.75).`,
  "hopf.title1": `<span class="number">5</span> The Hopf map, and the roll it cannot show`,
  "hopf.p1":
    `S³ does not fit on paper, so the paper draws its curves on the ordinary sphere with the <dfn id="def-hopf">Hopf
    map</dfn> (the paper's eq. 5):`,
  "hopf.p2":
    `<var>h</var>(<var>a</var>, <var>b</var>, <var>c</var>, <var>d</var>) = (<var>a</var>² + <var>b</var>² −
    <var>c</var>² − <var>d</var>², 2(<var>a</var><var>d</var> + <var>b</var><var>c</var>),
    2(<var>b</var><var>d</var> − <var>a</var><var>c</var>)) <span class="eq-no">(5)</span>`,
  "hopf.p3":
    `That is <var>q</var> i <var>q̄</var>: where the rotation sends the <var>x</var> axis, the aircraft's nose. A dot
    on S² is where the nose points, and <var>h</var>(<var>q</var>) = <var>h</var>(−<var>q</var>). For the paper's
    example, <var>h</var>(<var>p</var>) = (−1, 0, 0) and <var>h</var>(<var>r</var>) = (0, 1, 0).`,
  "hopf.p4":
    `What it cannot show is a roll about the nose. Here the roll <var>ρ</var> is a new turn added to section 2's turn
    <var>q</var>. It turns about the nose, as section 1's bank does, but it is added on top of <var>q</var> rather
    than being one of three angles. Roll the aircraft
    below: the wing goes round, the dot stays. The rolled rotation is <var>q</var> (cos(<var>ρ</var>/2) +
    sin(<var>ρ</var>/2) i), and it reads two ways. By section 2's rule (the right-hand factor turns first), it rolls
    about the world's <var>x</var> axis, where the nose starts, and then turns by <var>q</var>. Or it turns by
    <var>q</var> first and then rolls about the aircraft's own nose, wherever <var>q</var> has put it. The two give
    the same rotation. Every rotation of this form has the same image, so above each
    point of S² lies a whole circle of S³, its <dfn id="def-fibre">fibre</dfn>. The sphere is a faithful picture of
    where things point, and blind to how they are turned about that direction.`,
  "hopf.caption1":
    `The nose's point <var>h</var>(<var>q</var>) (orange) and a wing's (green) on the circle of directions square to
    the nose (“square to” means perpendicular to, at a right angle; for vectors, a dot product of 0). Drag or use
    the arrow keys to turn the sphere.`,
  "hopf.caption2": "The turn of section 2, then rolled about the nose.",
  "hopf.legend1": "Roll",
  "hopf.p5":
    `<output id="hopf-out">The nose points to (0.000, 1.000, 0.000); a wing to (−1.000, 0.000, 0.000).</output>`,
  "hopf.question1": "Predict, then check: roll by 180°. Where does the dot go?",
  "hopf.p6":
    `Guess, then <a class="set" href="?roll=180#hopf" data-state='{"roll":180}'>roll by 180°</a>.`,
  "hopf.p7":
    `<strong>Answer.</strong> Nowhere. The wing now points the opposite way, but the nose has not moved, and the dot
    is the nose. Both rotations lie on one fibre.`,
  "kuramoto.title1": `<span class="number">6</span> Oscillators falling into step`,
  "kuramoto.p1":
    `Fireflies flash together, pacemaker cells beat together. The <dfn id="def-kuramoto">Kuramoto model</dfn>
    (Kuramoto, 1975) is the simplest account: <var>N</var> oscillators with phases <var>θ<sub>i</sub></var> on a
    circle, each with its own natural frequency <var>ω<sub>i</sub></var>, each pulled towards the others. A phase is
    where an oscillator is in its cycle, an angle; its natural frequency is how fast that angle turns when nothing
    pulls it. Below, a prime means the rate of change in time, <var>θ</var>′ = d<var>θ</var>/d<var>t</var>, and the
    sum runs over every <var>j</var>:`,
  "kuramoto.p2":
    `<var>θ<sub>i</sub></var>′ = <var>ω<sub>i</sub></var> + (<var>K</var>/<var>N</var>) Σ<sub><var>j</var></sub>
    sin(<var>θ<sub>j</sub></var> − <var>θ<sub>i</sub></var>).`,
  "kuramoto.p3":
    `How much they agree is the <dfn id="def-order">order parameter</dfn>: the length <var>R</var> of their average
    point, (1/<var>N</var>) Σ e<sup>i<var>θ<sub>j</sub></var></sup>; 0 when they are scattered, 1 when in step (with different natural frequencies it levels off a little below 1:
    the fast ones stay a little ahead).
    Here i is the complex unit, i² = −1, and e<sup>i<var>θ</var></sup> = cos <var>θ</var> + i sin <var>θ</var> is
    the point at angle <var>θ</var> on the unit circle of the complex plane. It is not the quaternion part i of
    section 2: a quaternion has three such units, i, j and k, and on S³ below the average is taken of the quaternions
    themselves.
    Below, 20 phases have frequencies spread evenly from −0.5 to 0.5 (orange turn forwards, purple backwards). For
    many oscillators with such a spread, the pull wins once <var>K</var> passes 2/(π<var>g</var>(0)) ≈ 0.64, where
    <var>g</var>(0) = 1 is how densely the frequencies lie at their centre. Near that value the gathering is slow: on this figure's 12
    units of time, with 20 phases that start almost scattered, it shows clearly only from about <var>K</var> = 1.2.
    Set <var>K</var> and press <strong>Play
    from t = 0</strong>.`,
  "kuramoto.caption1":
    `The phases on their circle, the arrow their average point; beside it <var>R</var>(<var>t</var>) up to the
    end of the time bar, the time on show marked.`,
  "kuramoto.legend1": "Kuramoto phases",
  "kuramoto.p4": `<output id="phases-out">At t = 0.00, R = 0.049.</output>`,
  "kuramoto.p5":
    `Adding angles does not care about order, so this model is called <em>abelian</em>. Rotations do care: on S³ the
    product of quaternions is not commutative. M. A. Lohe, who generalised Kuramoto's model from phases to matrices
    (2009), named such models <em>non-abelian</em> Kuramoto models. On S³ the oscillators are unit quaternions
    <var>q<sub>i</sub></var> (the paper's eq. 1 is the model's general form, which also lets each oscillator turn on its own, like the
    <var>ω<sub>i</sub></var> above). All pulled by all, with no natural rotation of
    their own, each follows`,
  "kuramoto.p6":
    `<var>q<sub>i</sub></var>′ = (<var>K</var>/(2<var>N</var>)) Σ<sub><var>j</var></sub> (<var>q<sub>j</sub></var> −
    <var>q<sub>i</sub></var> <var>q̄<sub>j</sub></var> <var>q<sub>i</sub></var>),`,
  "kuramoto.p7":
    `where <var>q<sub>i</sub></var> <var>q̄<sub>j</sub></var> <var>q<sub>i</sub></var> is a product of quaternions,
    whose order matters. For unit quaternions it equals
    2(<var>q<sub>i</sub></var>·<var>q<sub>j</sub></var>)<var>q<sub>i</sub></var> − <var>q<sub>j</sub></var> (section
    7 uses the same identity), so each term is 2(<var>q<sub>j</sub></var> −
    (<var>q<sub>i</sub></var>·<var>q<sub>j</sub></var>) <var>q<sub>i</sub></var>): a pull towards each other
    oscillator with the part along <var>q<sub>i</sub></var> taken away.`,
  "kuramoto.p11":
    `A check on the circle: there this is the phase equation above with every <var>ω<sub>i</sub></var> = 0. Put <var>z<sub>i</sub></var> = e<sup>i<var>θ<sub>i</sub></var></sup>
    in place of <var>q<sub>i</sub></var>; then <var>z<sub>j</sub></var> − <var>z<sub>i</sub></var>
    <var>z̄<sub>j</sub></var> <var>z<sub>i</sub></var> = 2i sin(<var>θ<sub>j</sub></var> − <var>θ<sub>i</sub></var>)
    <var>z<sub>i</sub></var> and <var>z<sub>i</sub></var>′ = i<var>θ<sub>i</sub></var>′ <var>z<sub>i</sub></var>, so
    <var>θ<sub>i</sub></var>′ = (<var>K</var>/<var>N</var>) Σ<sub><var>j</var></sub> sin(<var>θ<sub>j</sub></var> −
    <var>θ<sub>i</sub></var>).`,
  "kuramoto.p12":
    `Now pin one of them at a rotation <var>r</var>, so that it never moves: it is the <dfn id="def-leader">leader</dfn>, and the others, the <em>followers</em>,
    fall into step and then settle on it. With one follower, <var>N</var> = 2 (the term with
    <var>j</var> = <var>i</var> is 0), the follower obeys
    <var>q</var>′ = (<var>K</var>/2)(<var>r</var> − (<var>q</var>·<var>r</var>) <var>q</var>): the paper's method
    (exactly at <var>K</var> = 2; another <var>K</var> runs the same path on a clock <var>K</var>/2 times as fast),
    next.`,
  "kuramoto.p13":
    `How much they agree is measured as on the circle: the order parameter on S³ is the length <var>R</var> =
    |(1/<var>N</var>) Σ<sub><var>j</var></sub> <var>q<sub>j</sub></var>| of the mean of the <var>q<sub>j</sub></var>
    as points of R⁴ (the leader counted too), 1 when all are at one point, small when they are spread over S³. It is not blind to the sign: <var>q</var> and
    −<var>q</var> average to 0, so <var>R</var> can be small while the rotations agree.`,
  "kuramoto.caption2":
    `Eight followers (purple, with their trails) and the pinned leader <var>r</var> (orange), drawn by the Hopf map;
    the sphere turns with the one in section 5.`,
  "kuramoto.legend2": "Rotations on S³",
  "kuramoto.p8":
    `<output id="lohe-out">At t = 0.00, R = 0.396; the farthest follower is a 174.5° turn from r.</output>`,
  "kuramoto.question1": "Predict, then check: with no coupling, K = 0, what does R do?",
  "kuramoto.p9":
    `Guess, then <a class="set" href="?K=0&amp;K3=0#kuramoto" data-state='{"coupling":0,"lohe":0}' data-play="phases">set K = 0 and
    play</a>.`,
  "kuramoto.p10":
    `<strong>Answer.</strong> Each phase turns at its own speed, <var>θ<sub>i</sub></var>(<var>t</var>) =
    <var>θ<sub>i</sub></var>(0) + <var>ω<sub>i</sub></var><var>t</var>, and nothing gathers them: <var>R</var>
    wanders near 0. On S³ with <var>K</var> = 0 nothing moves at all, since <var>q<sub>i</sub></var>′ = 0.`,
  "kli.title1": `<span class="number">7</span> KLI: the paper's flow`,
  "kli.p1":
    `<dfn id="def-kli">KLI</dfn>, Kuramoto–Lohe interpolation, the method of <a href="#paper">Kapić and Crnkić</a>,
    lets a rotation flow from <var>p</var> to <var>r</var> by the model (the paper's eq. 3)`,
  "kli.p2":
    `<var>q</var>′(<var>t</var>) = −½ (<var>q</var> <var>r̄</var> <var>q</var> − <var>r</var>), <var>q</var>(0) =
    <var>p</var>. <span class="eq-no">(3)</span>`,
  "kli.p3":
    `For a unit <var>q</var>, <var>q</var> <var>r̄</var> <var>q</var> = 2(<var>q</var>·<var>r</var>)<var>q</var> −
    <var>r</var>, so this is simply <var>q</var>′ = <var>r</var> − (<var>q</var>·<var>r</var>) <var>q</var>. (Why:
    <var>q</var> <var>r̄</var> and <var>r</var> <var>q̄</var> are each other's conjugates, so their sum is twice
    their real part, <var>q</var> <var>r̄</var> + <var>r</var> <var>q̄</var> = 2(<var>q</var>·<var>r</var>);
    multiply on the right by <var>q</var> and use <var>q̄</var> <var>q</var> = 1.) The figure shows why it works. (<var>q</var>·<var>r</var>)<var>q</var> is the part of <var>r</var> along
    <var>q</var>; what is left is square to <var>q</var>, a tangent of the sphere. A velocity square to <var>q</var>
    keeps |<var>q</var>| = 1, since d|<var>q</var>|²/d<var>t</var> = 2 <var>q</var>·<var>q</var>′ = 0. And it lies
    in the plane of <var>q</var> and <var>r</var>, so <var>q</var> never leaves the great circle through
    <var>p</var> and <var>r</var>: SLERP's arc.`,
  "kli.caption1":
    `The great circle through <var>p</var> and <var>r</var> (SLERP's arc dashed), <span class="kli">KLI</span>'s way
    so far, and at <var>q</var>(<var>t</var>) its velocity <var>q</var>′, the tangent part of <var>r</var>.`,
  "kli.p4":
    `<output id="kli-out">At t = 0.00, φ = 60.00°, s = 0.000: q = 0.000 + 0.000 i + 0.000 j + 1.000 k.</output>`,
  "kli.p5":
    `<strong>The time warp.</strong> Call <var>φ</var>(<var>t</var>) the angle between <var>q</var>(<var>t</var>) and
    <var>r</var>. Then cos <var>φ</var> = <var>q</var>·<var>r</var>, and its rate of change is
    <var>q</var>′·<var>r</var> = 1 − (<var>q</var>·<var>r</var>)² = sin²<var>φ</var>. It is also −sin <var>φ</var>
    · <var>φ</var>′, so <var>φ</var>′ = −sin <var>φ</var>. This separates, and ∫ d<var>φ</var>/sin <var>φ</var> = ln
    tan(<var>φ</var>/2), so its solution is tan(<var>φ</var>(<var>t</var>)/2) =
    tan(<var>φ</var>₀/2) e<sup>−<var>t</var></sup>. So <var>q</var>(<var>t</var>) is SLERP's point at
    <var>s</var>(<var>t</var>) = 1 − <var>φ</var>(<var>t</var>)/<var>φ</var>₀: the same path as SLERP, exactly, at
    another pace. This <var>s</var>(<var>t</var>) is KLI's <em>time warp</em>, how far along SLERP's arc it is at
    time <var>t</var> (the time bar sets <var>t</var>; the warp is what the flow makes of it). Its speed is <var>s</var>′ = −<var>φ</var>′/<var>φ</var>₀ = sin <var>φ</var>/<var>φ</var>₀: it starts at sin
    <var>φ</var>₀/<var>φ</var>₀ (0.827 for <var>φ</var>₀ = 60°) and slows down exponentially as it arrives. (The speed
    of <var>q</var> itself on the sphere at the start, |<var>q</var>′|, is sin <var>φ</var>₀.) In words:
    <var>q</var> moves along the part of <var>r</var> square to <var>q</var>, whose length is sin <var>φ</var>. Far from
    <var>r</var> that part is large; near <var>r</var> almost all of <var>r</var> lies along <var>q</var> and little is
    left to pull, so the angle left shrinks by nearly the same fraction in each unit of time and never reaches 0.
    That is why the method stops once <var>q</var> is within a tolerance of <var>r</var> (below).`,
  "kli.caption2":
    `<span class="kli">KLI</span>'s time warp <var>s</var>(<var>t</var>) against <span class="slerp">SLERP</span> run over the
    same time, <var>t</var>/<var>T</var>, where <var>T</var> is the time at which the method stops, once <var>q</var> is within the tolerance of <var>r</var> (worked
    out below: 11.66 for the paper's example).`,
  "kli.p6":
    `<dfn id="def-algorithm-1">Algorithm 1</dfn> of the paper computes the flow step by step: start at <var>q</var> =
    <var>p</var>; take a step of length <var>δ</var> in time (here by RK4, section 8); stop once ‖<var>r</var> −
    <var>q</var>‖ &lt; <var>ε</var> (the double bars are the length of a vector of R⁴, here of the four-vector
    <var>r</var> − <var>q</var>). Its two knobs are the tolerance <dfn id="def-epsilon"><var>ε</var></dfn>, how
    close is close enough, and the time step <dfn id="def-delta"><var>δ</var></dfn>. The paper uses <var>ε</var> =
    10⁻⁵ and <var>δ</var> = 0.01 and reports <var>T</var> = 11.66. Where that comes from: ‖<var>r</var> −
    <var>q</var>‖ = 2 sin(<var>φ</var>/2), so the flow first comes within <var>ε</var> at`,
  "kli.p7":
    `<var>T</var>* = ln( tan(<var>φ</var>₀/2) / tan(arcsin(<var>ε</var>/2)) ) = 11.6568 for the paper's example,`,
  "kli.p8":
    `and the loop stops at the first multiple of <var>δ</var> past it, 11.66. Step it yourself: <strong>Step
    δ</strong> moves the time bar on by one step, and the dot on the plot is that step's distance.`,
  "kli.caption3":
    `‖<var>r</var> − <var>q<sub>n</sub></var>‖ at each step <var>t<sub>n</sub></var> = <var>nδ</var> on a log scale,
    <var>ε</var> dashed, the stop <var>T</var>, and <var>T</var>* dotted.`,
  "kli.legend1": "Algorithm 1",
  "kli.p9":
    `<output id="steps-out">Step n = 0 at t = 0.00: ‖r − q‖ = 1.00e+0. With ε = 10⁻⁵ and δ = 0.01 the loop stops
    after 1166 steps, at T = 11.66; T* = 11.6568.</output>`,
  "kli.question1": "Predict, then check: at what time is KLI halfway along the arc?",
  "kli.p10":
    `Use the time bar: halfway means <var>φ</var> = 30°. Guess, then <a class="set" href="?t=0.77#kli" data-t="0.77">go
    to t = 0.77</a>.`,
  "kli.p11":
    `<strong>Answer.</strong> tan 15° = tan 30° e<sup>−<var>t</var></sup> gives <var>t</var> = ln(tan 30° / tan 15°)
    = 0.768, a fifteenth of the way to <var>T</var>. The second half takes the other 14 parts: fast start, slow
    arrival.`,
  "kli.question2": "Predict, then check: one more digit, ε = 10⁻⁶. How much longer does Algorithm 1 run?",
  "kli.p12":
    `Guess, then <a class="set" href="?digits=6#kli" data-state='{"digits":6}'>set ε = 10⁻⁶</a>.`,
  "kli.p13":
    `<strong>Answer.</strong> For small <var>ε</var>, tan(arcsin(<var>ε</var>/2)) ≈ <var>ε</var>/2, so each digit
    adds ln 10 ≈ 2.303 to <var>T</var>*: 13.9594, and the loop stops at <var>T</var> = 13.96. The time bar and the
    plots' axes now run to 15, so the stop <var>T</var> and <var>T</var>* show. The distance falls by
    e<sup>−<var>t</var></sup>, a straight line on the log plot.`,
  "kli.question3": "A note for readers of the paper: the printed eq. 4 and Table 1",
  "kli.p14":
    `The paper writes eq. 3 out in components as <var>q<sub>i</sub></var>′ = <var>r<sub>i</sub></var> −
    <var>q<sub>i</sub></var> − <var>q<sub>i</sub></var> cos <var>θ</var> (eq. 4), where <var>q<sub>i</sub></var> and
    <var>r<sub>i</sub></var> are the four parts of <var>q</var> and <var>r</var> (not oscillators, as in section 6)
    and the paper's <var>θ</var> is this tour's <var>φ</var>. The extra
    −<var>q<sub>i</sub></var> is a typo: with it the flow leaves the sphere and settles at a point of length (√5 −
    1)/2 ≈ 0.618, never reaching <var>r</var>. The right form is <var>q<sub>i</sub></var>′ =
    <var>r<sub>i</sub></var> − <var>q<sub>i</sub></var> cos <var>θ</var>, with cos <var>θ</var> =
    <var>q</var>·<var>r</var>, and the paper's Table 1 matches it. In Table 1 the row at <var>t</var> = 1.8 repeats
    the row at 1.2; the right values are 0.4364 + 0.4364 i + 0.4364 j + 0.6548 k. Both are checked on <a
    href="math.html#the-papers-example-section-3">the mathematics page</a> and by the project's tests.`,
  "integrators.title1": `<span class="number">8</span> Integrators and drift`,
  "integrators.p1":
    `A computer takes the flow in steps of length <var>h</var> in time: the same as Algorithm 1's <var>δ</var> in
    section 7, called <var>h</var> here because this figure has its own slider. <strong>Euler's</strong> step (the same Euler as the angles and the axis, a third
    idea of his),
    <var>q</var> + <var>h</var> <var>q</var>′, moves along the tangent, and a tangent step always leaves the sphere:
    |<var>q</var> + <var>h</var><var>v</var>|² = 1 + <var>h</var>²|<var>v</var>|² when <var>v</var> is square to
    <var>q</var>. <dfn id="def-rk4">RK4</dfn>, the classical fourth-order Runge–Kutta method, samples the slope four
    times in a step and takes their weighted average, (<var>k</var>₁ + 2<var>k</var>₂ + 2<var>k</var>₃ +
    <var>k</var>₄)/6, where <var>k</var>₁ to <var>k</var>₄ are the four slopes (not the quaternion unit k); its error shrinks like <var>h</var>⁴, and so does its drift off the sphere.`,
  "integrators.p5":
    `The <strong>geodesic</strong> step takes RK4's increment <var>Δ</var> and, instead of adding it, walks along the
    great circle towards it: to <var>q</var> cos <var>α</var> + <var>u</var> sin <var>α</var>, where <var>u</var> is
    the unit vector along the part of <var>Δ</var> square to <var>q</var> and <var>α</var> is the angle between
    <var>q</var> and <var>q</var> + <var>Δ</var>. Two unit vectors square to each other, weighted by the cosine and
    the sine of one angle, always give length 1, so |<var>q</var>| = 1 by construction. This flow, written <var>q</var>′ = <var>r</var> − (<var>q</var>·<var>r</var>)<var>q</var> (the
    form this page integrates; off the sphere it differs from eq. 3's −½(<var>q</var> <var>r̄</var> <var>q</var> −
    <var>r</var>)), pulls a stray |<var>q</var>| back towards 1: for any
    <var>q</var>, d|<var>q</var>|²/d<var>t</var> = 2 <var>q</var>·<var>q</var>′ = 2(<var>q</var>·<var>r</var>)(1 −
    |<var>q</var>|²), which shrinks |<var>q</var>| when it is above 1 and grows it when below, as long as
    <var>q</var>·<var>r</var> &gt; 0 (on the way from <var>p</var> to <var>r</var>, always). So here the drift does
    not grow for ever; in other flows it can.`,
  "integrators.caption1":
    `| |<var>q</var>| − 1 | on the paper's example for each integrator at step <var>h</var>, on a log scale (what is
    below 10⁻¹⁷ is drawn at 10⁻¹⁷); the chosen one thick. Late in the run Euler's line can fall below RK4's: at a
    large step Euler runs ahead of the true flow and arrives early, and a <var>q</var> that has all but stopped no
    longer drifts. That is an error in timing, not better accuracy.`,
  "integrators.legend1": "Integrators",
  "integrators.p2":
    `<output id="drift-out">The largest drift at h = 0.5: Euler 9.0e-2, RK4 1.5e-3, geodesic 2.2e-16.</output>`,
  "integrators.question1":
    `Predict, then check: halve the step from 0.5 to 0.25. How much smaller do Euler's and RK4's drifts get?`,
  "integrators.p3":
    `Hint: a drift that goes like <var>h</var><sup><var>p</var></sup> gets 2<sup><var>p</var></sup> times smaller
    when <var>h</var> is halved, and RK4's goes like <var>h</var>⁴. For Euler, work out the drift of its first step
    from the formula above, √(1 + <var>h</var>²|<var>v</var>|²) − 1 with |<var>v</var>| = sin 60° = 0.866, at
    <var>h</var> = 0.5 and at 0.25, and ask whether the first step is still the worst one at 0.25. Guess, then <a
    class="set" href="?h=0.25#integrators" data-state='{"step":0.25}'>set h = 0.25</a>.`,
  "integrators.p4":
    `<strong>Answer.</strong> Euler's about 2.8 times (0.090 to 0.032), RK4's about 23 times (1.5·10⁻³ to 6.5·10⁻⁵).
    Euler's drift is not many small errors piling up. At <var>h</var> = 0.5 the largest drift is the very first
    step: from <var>p</var> with velocity <var>v</var>, |<var>v</var>| = sin <var>φ</var>₀ = 0.866, it lands at
    length √(1 + <var>h</var>²|<var>v</var>|²), a drift of √(1 + 0.1875) − 1 = 0.090; after it the flow pulls
    |<var>q</var>| back (0.057, then 0.017). At <var>h</var> = 0.25 the first step gives √(1 + 0.047) − 1 = 0.023
    and the second pushes out a little further, to 0.032, before the pull wins. Why in between: each Euler step
    pushes |<var>q</var>|² out by <var>h</var>²|<var>v</var>|² and, by the formula for d|<var>q</var>|²/d<var>t</var>
    above, pulls the excess |<var>q</var>|² − 1 back by about 2<var>h</var>(<var>q</var>·<var>r</var>) times itself.
    The two balance at an excess of about <var>h</var>|<var>v</var>|²/(2<var>q</var>·<var>r</var>), proportional to
    <var>h</var>: halving <var>h</var> halves it. A first step's drift, about <var>h</var>²|<var>v</var>|²/2, gets 4
    times smaller instead. At <var>h</var> = 0.5 the worst drift is the first step; at 0.25 it is a later one, on its
    way to the balance: 2.8 lies between 2 and 4. RK4's goes like <var>h</var>⁴ (2⁴ = 16, a little more at this large step). The geodesic step stays
    at rounding, about 10⁻¹⁶.`,
  "many.title1": `<span class="number">9</span> Many rotations`,
  "many.p1":
    `The paper interpolates between two rotations and leaves many as an open question. The other pages of this site
    take it up; each figure below is a live one from its page, loaded as you reach it.`,
  "many.heading1": "Keyframes: a smooth turn through many",
  "many.p2":
    `An animator sets a character's joints at a few moments, the keyframes, and the computer fills in the rest. SLERP
    from key to key turns at a steady rate on each piece but snaps round at every key, where the axis and speed change at
    once: a jump in angular velocity (the turning rate, a vector along the axis; <a href="#def-omega">defined below</a>), a visible snap on
    screen and a kick of torque (the twist a motor must apply) for a motor or a gimbal. The KLI chain (the figure's
    key calls it the Kuramoto–Lohe chain) on <a href="keyframes.html">Many rotations</a> samples the whole curve densely on S³ and pins the samples at
    the keys (pinned leaders, section 6); every other sample follows a Kuramoto–Lohe flow, drawn by its neighbours and
    pushed off by its second neighbours, and settles on a curve through the keys whose turning rate changes smoothly.
    (Between two keys alone it is SLERP's arc, as KLI is.) Move <em>smoothness</em> from 0 (piecewise SLERP) to 1. The figure draws where the nose
    points (the Hopf map of section 5) along three curves through the same keys: the KLI chain (orange, solid), <dfn
    id="def-squad">Squad</dfn> (Shoemake's spline of quaternions, the usual smooth curve of animation software,
    built from SLERPs between extra control points; purple, dashed) and piecewise SLERP (dark, dotted). The white
    dots k0, k1, … are the keys; k0 and k1 share one dot, since the first piece is a pure turn about the nose, which
    the Hopf map cannot show (section 5). Watch k2 and the piece after it: as smoothness grows, the orange chain rounds
    the corner SLERP makes at k2 and leaves the dotted arc. The figure plays on its own clock, from k0 at
    <var>t</var> = 0 to k3 at <var>t</var> = 3, and then starts again; the three small filled dots are the three curves'
    points at the same moment <var>t</var>. If your system is set to reduce motion, the figure holds still at
    <var>t</var> = 2.5, between k2 and k3, where the curves part.`,
  "many.p10":
    `The figure above shows where the nose points, not how fast the object turns, and a kink in how fast is what a
    viewer sees. At each moment a turning object turns about some axis at some rate. Its <dfn id="def-omega">turning rate</dfn>, the
    angular velocity <var>ω</var>(<var>t</var>) (not the natural frequencies <var>ω<sub>i</sub></var> of section 6),
    is the vector along that axis whose length |<var>ω</var>| is the
    rate, in radians per unit of time (with quaternions, <var>q</var>′ = ½ <var>ω</var> <var>q</var>). SLERP from
    key to key turns about one fixed axis at one steady rate on each piece: a piece that turns by <var>θ</var> in a
    time Δ<var>t</var> has |<var>ω</var>| = <var>θ</var>/Δ<var>t</var>. At a key the next piece takes over with
    another axis and rate, so <var>ω</var> jumps: the angular acceleration <var>ω̇</var>, the rate at which
    <var>ω</var> changes, is unbounded there, an impulse: a kick. In an animation that is a visible snap at the keyframe; for a camera, a shake in the picture;
    for a motor or a robot's joint, a spike of torque (about a fixed axis, torque is the moment of inertia times the angular
    acceleration; in three dimensions, τ = <var>I</var><var>ω̇</var> + <var>ω</var> × <var>I</var><var>ω</var>,
    where <var>I</var> is now the inertia matrix, not the identity of section 1), which strains the gears and sets the arm vibrating. The smoothness slider sets the KLI chain
    from 0, piecewise SLERP itself, to 1, its smoothest; at any smoothness above 0, <var>ω</var> and even <var>ω̇</var> change
    without a jump. Below, the turning rate along the chain through the same four keys, k0 at <var>t</var> = 0 to k3 at
    <var>t</var> = 3: the keyframes' own time, not the time bar's.`,
  "many.caption1":
    `Left (above, on a narrow screen): |<var>ω</var>(<var>t</var>)| of the <span class="kli">KLI chain</span> at the
    chosen smoothness (thick) and of piecewise SLERP (dark, dotted), the keys as dotted lines, and the chain's jump
    of <var>ω</var> written at each key where it has one. Right (below): the chain's <var>ω</var> in its
    <span class="x">x</span>, <span class="y">y</span> and <span class="z">z</span> parts.`,
  "many.p11":
    `<output id="rates-out">At smoothness 1 ω has no jump at any key; its largest rate of change |ω̇| is 5.9 rad per
    unit time². Piecewise SLERP jumps by 2.92 rad per unit time at k1.</output>`,
  "many.p12":
    `Any smoothness above 0 already takes the jumps away: the chain's curve is then C² (the rotation has two
    continuous derivatives, so neither <var>ω</var> nor <var>ω̇</var> jumps), and <var>ω</var> can only change
    quickly near a key, never at once. What a small smoothness costs is a large, though finite,
    |<var>ω̇</var>| near the keys; at 1 the change is spread along the whole curve. What the chain makes smallest there is how
    much the curve bends in R⁴: its samples minimise a sum that stands for ∫|<var>q</var>″|² d<var>t</var>, where
    <var>q</var>″ is the second derivative of <var>q</var>(<var>t</var>). Since |<var>q</var>″|² =
    |<var>ω̇</var>|²/4 + |<var>ω</var>|⁴/16, that sum trades angular acceleration against uneven speed. So the
    curve at 1 is not the one with the least ∫|<var>ω̇</var>|² d<var>t</var> through the keys, though on random keys
    its ∫|<var>ω̇</var>|² is about 0.8 of Squad's (0.78–0.84 in the project's measurements; <a
    href="math.html#many-rotations-the-kuramotolohe-chain-the-papers-open-question">the mathematics page</a>). Slide from 1 down to 0.05 and watch the
    quoted |<var>ω̇</var>| grow, then to 0, where it has no bound at all.`,
  "many.question2":
    `Predict, then check: at smoothness 0, both pieces that meet at k2 turn by 122.6° (2.14 rad) in one unit of
    time, so |ω| is 2.14 on both sides. Does ω jump at k2, and by how much?`,
  "many.p13":
    `Guess, then <a class="set" href="?smooth=0#many-keyframes" data-state='{"smoothness":0}'>set the smoothness to
    0</a> and look at k2 in both plots.`,
  "many.p14":
    `<strong>Answer.</strong> Yes, by 2.53 rad per unit time. The turning rate is a vector: its length stays 2.14,
    but its axis swings in an instant through 72.6°, from (−0.410, 0.730, 0.547) to (0.730, 0.410, 0.547), and the jump
    is the length of the difference, 2 × 2.14 × sin(72.6°/2) = 2.53. So the plot of |<var>ω</var>| has no step at k2,
    while the <var>x</var> and <var>y</var> parts of <var>ω</var> step (<var>z</var> stays at 1.17). A jolt needs no change of
    speed, only of direction: a car that takes a sharp corner without braking still throws its passengers sideways.
    The largest jump is at k1, 2.92, where the axis and the rate both change.`,
  "many.heading2": "The swarm: synchronisation, or its opposite",
  "many.p3":
    `Drones agreeing on a heading, satellites on an attitude (a craft's orientation in space), a flock turning as
    one: many rotations coupled by the non-abelian Kuramoto (Lohe) model of section 6, all pulled by all, with no
    leader. In the figure, from <a href="swarm.html">The swarm</a>, each of the 200 dots is one rotation, drawn by
    the Hopf map where it points the nose. They start scattered at random over S³. The coupling <var>K</var> sets the
    pull. With <var>K</var> &gt; 0 each is drawn towards the others: at <var>K</var> = 1 they gather into a single
    dot by <var>t</var> = 8 on the figure's own clock, not the time bar's (<dfn id="def-sync">synchronisation</dfn>, the order parameter <var>R</var> going to 1).
    With <var>K</var> &lt; 0 the pull becomes a push. Pin one of them, a leader as in section 6, and the rest
    gather on it instead; with a single follower, that is KLI (exactly at <var>K</var> = 2; another <var>K</var>
    runs the same path on a clock <var>K</var>/2 times as fast). The swarm page can pin leaders, and has KLI as a
    preset.`,
  "many.question3":
    `Predict, then check: at K = 1 the dots gather into one. At K = −1 each pushes the others away. Do they fly
    apart?`,
  "many.p15":
    `Guess, then <button type="button" class="set-figure" data-figure="fig-swarm" data-attribute="coupling"
    data-value="-1">set K = −1</button> and watch the dots.`,
  "many.p16":
    `<strong>Answer.</strong> No: they hardly move, the farthest by a turn of about 5°. For identical oscillators all pulled
    by all, the flow raises <var>K</var>|<var>m</var>|², where <var>m</var> = (1/<var>N</var>)
    Σ<sub><var>j</var></sub> <var>q<sub>j</sub></var> is their mean and <var>R</var> = |<var>m</var>|. A push
    (<var>K</var> &lt; 0) lowers |<var>m</var>| to 0, which is called <em>balancing</em>. But 200 rotations
    scattered at random already have a mean near 0, <var>R</var> = 0.034 at the start, so a small nudge balances
    them: <var>R</var> is 0.000 by <var>t</var> = 8 on the figure's own clock. Apart is where they already were.`,
  "many.heading3": "Averaging: one rotation from many noisy ones",
  "many.p4":
    `A robot's camera measures its orientation many times, each a little off, and a few badly off: those are <dfn
    id="def-outlier">outliers</dfn>. One follower is pulled by all the measurements at once, each pull towards
    <var>r<sub>j</sub></var> weighted by <var>q</var>·<var>r<sub>j</sub></var>. Replace <var>r<sub>j</sub></var> by
    −<var>r<sub>j</sub></var> and both the pull and its weight change sign, so their product does not: the signs do
    not matter. The follower settles on the <dfn id="def-chordal">chordal mean</dfn>, the rotation <var>q</var> that
    maximises Σ(<var>q</var>·<var>r<sub>j</sub></var>)².`,
  "many.p17":
    `<em>Chordal</em> means that distance is measured straight through, between the 3 × 3 rotation matrices
    <var>R<sub>q</sub></var> and <var>R<sub>j</sub></var> of <var>q</var> and <var>r<sub>j</sub></var>, not along the
    sphere; the size of a matrix here is the square root of the sum of the squares of its nine entries. If the two
    rotations differ by a turn <var>θ</var>, then ‖<var>R<sub>q</sub></var> − <var>R<sub>j</sub></var>‖² = 3 + 3 −
    2(1 + 2 cos <var>θ</var>) = 4 − 4 cos <var>θ</var>: each matrix has three unit columns, and the nine entries of
    one times the other's, added, give 1 + 2 cos <var>θ</var>, the trace of a turn by <var>θ</var>. Since
    <var>θ</var> = 2<var>φ</var> (section 3) and cos 2<var>φ</var> = 2(<var>q</var>·<var>r<sub>j</sub></var>)² − 1,
    this is 8(1 − (<var>q</var>·<var>r<sub>j</sub></var>)²), the same for <var>r<sub>j</sub></var> and
    −<var>r<sub>j</sub></var>: a short chord is a large dot product. (The squared chord between the quaternions
    themselves, |<var>q</var> − <var>r<sub>j</sub></var>|² = 2 − 2 <var>q</var>·<var>r<sub>j</sub></var>, gives
    instead the <em>quaternion mean</em>: the four numbers of the measurements averaged, then divided by the length.
    It depends on the signs, so they are first put all on one side of S³.)`,
  "many.p18":
    `The <dfn id="def-karcher">Karcher mean</dfn> instead minimises the sum of squared turning angles to the
    measurements. Both are dragged by outliers. The <dfn id="def-median">median</dfn>, the rotation with the least
    summed angle (not squared) to the measurements, is dragged much less: a wild one pulls on it no harder than a near
    one. <a href="average.html">Averaging</a> computes all four.`,
  "many.p19":
    `Move the share of wild measurements. In the figure each dot is where a measurement points the nose, its Hopf
    image <var>h</var>(<var>r<sub>j</sub></var>); the wild ones have a colour of their own and are ringed once the
    median has set them aside. ★ is the truth, ● the follower on its way from 1. The four means are white discs ringed
    in their colour: the chordal mean orange, the quaternion mean green, the Karcher (geodesic) mean purple, the
    median blue. (The figure's key names each; the <a href="average.html">Averaging</a> page sets them beside bars of
    the same colours.)`,
  "many.heading4": "Synchronising rotations on a graph",
  "many.p5":
    `A robot mapping a building (SLAM, simultaneous localisation and mapping: it builds the map and finds itself in
    it at the same time) or photos stitched into a 3D model give rotations measured between pairs: camera
    <var>j</var> relative to camera <var>i</var>, <var>R<sub>ij</sub></var> = <var>R<sub>i</sub></var>ᵀ<var>R<sub>j</sub></var>. Finding every rotation from these is synchronisation on a graph:
    each camera a node, each measurement an edge. The answer is the one with the smallest chordal cost <var>f</var>
    = Σ ‖<var>R<sub>i</sub></var> <var>R<sub>ij</sub></var> − <var>R<sub>j</sub></var>‖², the sum over the edges of
    how far each measurement misses, squared (the same straight-through distance, here between matrices).`,
  "many.p6":
    `A search for the smallest <var>f</var> goes downhill, and downhill can end in a hollow that is not the lowest
    one. On <a href="sync.html">Synchronising rotations</a> the answer comes with a <dfn
    id="def-certificate">certificate</dfn>, a test made afterwards: from the answer and the measurements, build one
    large symmetric matrix; if its smallest eigenvalue is not negative, it can be proved that no choice of rotations
    at all has a smaller <var>f</var>, so the answer is the best there is, not just the best nearby. (If the test
    fails, nothing is proved either way.) Wrong edges, the graph's outliers, are found and set aside.`,
  "many.p7":
    `In the figure, <var>f</var> is printed at the top as the flow lowers it: the paper's model run on the graph,
    each node pulled towards where each of its edges says it should be. Each edge is coloured by how far its
    measurement disagrees with the current answer: blue under 2°, teal 2–5°, green 5–15°, orange 15–45°, red 45° or
    more; a wrong edge is dashed. Measurements between pairs cannot fix every node: turn all the nodes by one common
    rotation <var>G</var>, and each (<var>G</var> <var>R<sub>i</sub></var>)ᵀ(<var>G</var> <var>R<sub>j</sub></var>) =
    <var>R<sub>i</sub></var>ᵀ<var>R<sub>j</sub></var> stays the same. So the answer is compared with the truth only
    after the one common turn that lines them up best. Each node then carries a needle: the turn still left between
    its true rotation and the answer's, applied to the body's <var>x</var> axis and seen from above. The needle points
    right once the node agrees with the truth.`,
  "many.question1":
    `Predict, then check: on the averaging figure, with half the measurements wild, which means stay near the truth?`,
  "many.p8":
    `Guess, then <button type="button" class="set-figure" data-figure="fig-average" data-attribute="outliers"
    data-value="0.5">set half of them wild</button>.`,
  "many.p9":
    `<strong>Answer.</strong> The quaternion mean (green) and the Karcher mean (purple) are pulled farthest, about
    11° and 12°; the chordal mean (orange) less, about 6°, since a wild one's squared chord can never exceed 8; the
    median (blue), which counts each by its distance alone, stays within about 2°, as the table on <a
    href="average.html">Averaging</a> shows.`,
  "glossary.title1": "Glossary",
  "glossary.term1": "Algorithm 1",
  "glossary.definition1":
    `The paper's loop: step the flow by <var>δ</var> from <var>p</var> until within <var>ε</var> of <var>r</var>. <a
    href="#def-algorithm-1">Section 7</a>`,
  "glossary.term28": "angular velocity (turning rate)",
  "glossary.definition28":
    `<var>ω</var>, the vector along the axis a rotation is turning about, its length the rate in radians per unit
    time; <var>q</var>′ = ½ <var>ω</var> <var>q</var>. A jump in it is an unbounded angular acceleration, an
    impulse: a kick. <a href="#def-omega">Section 9</a>`,
  "glossary.term2": "certificate",
  "glossary.definition2":
    `A check that a computed answer is the best of all, not just locally. <a href="#def-certificate">Section 9</a>`,
  "glossary.term3": "chordal mean",
  "glossary.definition3":
    `The rotation that maximises Σ(<var>q</var>·<var>r<sub>j</sub></var>)² over the measurements. <a
    href="#def-chordal">Section 9</a>`,
  "glossary.term4": "double cover",
  "glossary.definition4":
    `<var>q</var> and −<var>q</var> are one rotation: S³ covers the rotations twice. <a
    href="#def-double-cover">Section 3</a>`,
  "glossary.term5": "δ (delta)",
  "glossary.definition5":
    `Algorithm 1's time step; the paper's is 0.01 (section 8 calls a step <var>h</var>). <a href="#def-delta">Section
    7</a>`,
  "glossary.term6": "ε (epsilon)",
  "glossary.definition6":
    `Algorithm 1's tolerance: stop once ‖<var>r</var> − <var>q</var>‖ &lt; <var>ε</var>; the paper's is 10⁻⁵. <a
    href="#def-epsilon">Section 7</a>`,
  "glossary.term7": "fibre",
  "glossary.definition7":
    `The circle of S³ that the Hopf map sends to one point of S²: the rotations that differ by a roll about the nose.
    <a href="#def-fibre">Section 5</a>`,
  "glossary.term8": "geodesic",
  "glossary.definition8":
    `A shortest path on a curved surface; on a sphere, an arc of a great circle. <a href="#def-geodesic">Section
    3</a>`,
  "glossary.term9": "Hopf map",
  "glossary.definition9":
    `<var>h</var>: S³ → S², <var>h</var>(<var>q</var>) = <var>q</var> i <var>q̄</var>, where the nose points (the
    paper's eq. 5). <a href="#def-hopf">Section 5</a>`,
  "glossary.term10": "Karcher mean",
  "glossary.definition10":
    `The rotation that minimises the sum of squared turning angles to the measurements (the geodesic mean). <a
    href="#def-karcher">Section 9</a>`,
  "glossary.term11": "KLI",
  "glossary.definition11":
    `Kuramoto–Lohe interpolation: the paper's flow <var>q</var>′ = <var>r</var> −
    (<var>q</var>·<var>r</var>)<var>q</var> from <var>p</var> to <var>r</var>. <a href="#def-kli">Section 7</a>`,
  "glossary.term12": "Kuramoto model",
  "glossary.definition12":
    `Oscillators with their own frequencies, each pulled towards the others' phases. <a href="#def-kuramoto">Section
    6</a>`,
  "glossary.term13": "order parameter",
  "glossary.definition13":
    `<var>R</var>, the length of the oscillators' average point (on S³, of the mean of the <var>q<sub>j</sub></var>):
    0 scattered, 1 in step. <a href="#def-order">Section 6</a>`,
  "glossary.term14": "outlier",
  "glossary.definition14": `A measurement far off the truth, not just noisy. <a href="#def-outlier">Section 9</a>`,
  "glossary.term15": "quaternion",
  "glossary.definition15":
    `A number <var>a</var> + <var>b</var> i + <var>c</var> j + <var>d</var> k with i² = j² = k² = ijk = −1. <a
    href="#def-quaternion">Section 2</a>`,
  "glossary.term16": "RK4",
  "glossary.definition16":
    `The classical fourth-order Runge–Kutta method: four slopes a step, error like <var>h</var>⁴. <a
    href="#def-rk4">Section 8</a>`,
  "glossary.term17": "S³",
  "glossary.definition17":
    `The 3-sphere: the points of R⁴ at distance 1 from the origin, the unit quaternions. <a href="#def-s3">Section
    3</a>`,
  "glossary.term18": "SLERP",
  "glossary.definition18":
    `Spherical linear interpolation: the great-circle arc from <var>p</var> to <var>r</var> at constant speed. <a
    href="#def-slerp">Section 4</a>`,
  "glossary.term19": "Squad",
  "glossary.definition19":
    `Shoemake's spline of quaternions: a smooth curve through many keys, built from SLERPs. <a
    href="#def-squad">Section 9</a>`,
  "glossary.term20": "synchronisation",
  "glossary.definition20":
    `Bringing many rotations into agreement: in step with each other (the swarm), or consistent with measurements
    between pairs (a graph). <a href="#def-sync">Section 9</a>`,
  "glossary.term21": "unit quaternion",
  "glossary.definition21":
    `A quaternion of length 1; each is a rotation, and each rotation is two of them. <a
    href="#def-unit-quaternion">Section 2</a>`,
  "glossary.term22": "conjugate",
  "glossary.definition22":
    `Of <var>q</var> = <var>a</var> + <var>b</var> i + <var>c</var> j + <var>d</var> k: <var>q̄</var> = <var>a</var> −
    <var>b</var> i − <var>c</var> j − <var>d</var> k; for a unit quaternion, the opposite turn. <a href="#turn">Section 2</a>`,
  "glossary.term23": "dot product",
  "glossary.definition23":
    `Of two quaternions, <var>p</var>·<var>r</var>: their four parts multiplied in pairs and added; for unit ones, the
    cosine of the angle <var>φ</var> between them. <a href="#cover">Section 3</a>`,
  "glossary.term24": "great circle",
  "glossary.definition24":
    `Where a sphere meets a plane through its centre: the sphere's largest circles, and its shortest paths. <a
    href="#def-geodesic">Section 3</a>`,
  "glossary.term25": "keyframe",
  "glossary.definition25":
    `An orientation given at a moment (an animator's, a robot's waypoint) that a smooth turn must pass through. <a
    href="#many">Section 9</a>`,
  "glossary.term26": "Lohe model",
  "glossary.definition26":
    `Kuramoto's model grown from phases on a circle to rotations on S³ (the non-abelian Kuramoto model): each unit
    quaternion pulled along the sphere towards the others. <a href="#kuramoto">Section 6</a>`,
  "glossary.term27": "pinned leader",
  "glossary.definition27":
    `An oscillator of the Lohe model held still, which the others (the followers) flow to; with one follower, KLI. <a
    href="#def-leader">Section 6</a>`,
  "glossary.term29": "median",
  "glossary.definition29":
    `Of rotations: the one with the least summed angle (not squared) to the measurements, so that a wild one pulls on
    it no harder than a near one. <a href="#def-median">Section 9</a>`,
  "paper.title1": "References",
  "paper.item1":
    `Zinaid Kapić and Aladin Crnkić, “Interpolating Rotations with Non-abelian Kuramoto Model on the 3-Sphere”,
    preprint, Faculty of Technical Engineering, University of Bihać. Equations (3) and (5), Algorithm 1, Table 1 and
    <var>T</var> = 11.66 are quoted from it; its supplementary video: <a
    href="https://www.youtube.com/watch?v=IkE_olufAuI">youtube.com/watch?v=IkE_olufAuI</a>.`,
  "paper.item2":
    `Y. Kuramoto, “Self-entrainment of a population of coupled non-linear oscillators”, Lecture Notes in Physics 39,
    Springer, 1975.`,
  "paper.item3":
    `M. A. Lohe, “Non-Abelian Kuramoto models and synchronization”, Journal of Physics A 42, 395101, 2009.`,
  "paper.item4": "K. Shoemake, “Animating rotation with quaternion curves”, SIGGRAPH 1985.",
  "save.intro":
    `Each figure of the tour as it stands now, as a picture (PNG, twice the screen's resolution) or for print (SVG,
    vector); Algorithm 1's path on the paper's example as data.`,
  "footer.p1":
    `Rust → WebAssembly; every number on this page is computed in your browser by the code of the npm package
    <code>kli</code>. Keys: Space play/pause, ← → step the time bar, Home restart; arrows turn the sphere of section 5
    when it has focus. Next: try the paper's two rotations on <a href="index.html">KLI: two rotations</a>.`,
  "care.label1": "Yaw",
  "care.label2": "Pitch",
  "care.label3": "Bank",
  "turn.label1": "Axis",
  "turn.label2": "Angle θ",
  "slerp.label1": "s",
  "hopf.label1": "Roll ρ",
  "kuramoto.label1": "Coupling K",
  "kuramoto.label2": "Coupling K",
  "kli.label1": "Digits of ε",
  "kli.label2": "Step δ",
  "integrators.label1": "Integrator",
  "integrators.label2": "Step h",
  "many.legend1": "Keyframes",
  "many.label1": "Smoothness",
  "many.label2": "Coupling K",
  "many.label3": "Share of wild ones",
  "many.label4": "Share of wrong edges",
  "clock.label1": "Time",
  "care.value1": "30° yaw",
  "care.value2": "40° pitch",
  "care.value3": "0° bank",
  "turn.option1": "diagonal, (1, 1, 1)/√3",
  "turn.value1": "90° about z",
  "hopf.value1": "0° roll about the nose",
  "kuramoto.button1": "Play from t = 0",
  "kuramoto.button2": "Play from t = 0",
  "kli.button1": "Back δ",
  "kli.button2": "Step δ",
  "kli.button3": "Play from t = 0",
  "integrators.option1": "geodesic",
  "many.fallback1":
    `The live figure of <a href="keyframes.html">Many rotations</a> comes here as you reach it.`,
  "many.fallback2": `The live figure of <a href="swarm.html">The swarm</a> comes here as you reach it.`,
  "many.fallback3": `The live figure of <a href="average.html">Averaging</a> comes here as you reach it.`,
  "many.fallback4":
    `The live figure of <a href="sync.html">Synchronising rotations</a> comes here as you reach it.`,
  "clock.button1": "Play",
  "clock.button2": "Restart",
  "clock.link1": "Link to this view",
  "contents.aria1": "Contents",
  "care.aria1": "An aircraft turned by yaw, pitch and bank, with its yaw, pitch and bank axes drawn as dashed lines.",
  "turn.aria1": "The aircraft turned about the chosen axis by the chosen angle, the axis drawn through it, its four numbers below.",
  "cover.aria1": "A circle of S³ through 1 and the axis, with q and minus q on it as opposite points, and the aircraft turned by q and by minus q, which look the same.",
  "cover.aria2": "Set the angle θ",
  "slerp.aria1": "The arc of S³ from p to r with the SLERP point and the NLERP point at s, and ticks every 0.1 of s for each: even for SLERP, uneven for NLERP.",
  "hopf.role1": "turnable sphere",
  "hopf.aria1": "The sphere S² with the nose's point h(q) and the wing's point, on the circle of directions perpendicular to the nose. Arrow keys turn the sphere; dragging turns it too.",
  "hopf.aria2": "The aircraft of section 2, rolled about its nose by the chosen angle.",
  "kuramoto.aria1": "Twenty phases as dots on a circle with the order parameter as an arrow from the centre, and beside them the order parameter R against time.",
  "kuramoto.aria2": "Eight followers on S³, drawn by their Hopf images on the sphere with trails, flowing to a pinned leader r.",
  "kli.aria1": "The great circle through p and r with q at the time on show, r split into its part along q and the tangent part, which is q prime.",
  "kli.aria2": "How far along the arc KLI is against time, a fast rise that levels off, beside SLERP's straight line reaching the end at T.",
  "kli.aria3": "The distance from r at each step of Algorithm 1 on a log scale, falling in a straight line until it passes below epsilon at T.",
  "integrators.aria1": "The drift of the length of q from 1 against time on a log scale for Euler, RK4 and the geodesic step, the chosen one drawn thick.",
  "many.figure1": "The Hopf curves through four keyframes",
  "many.aria1":
    "The turning rate against time through four keyframes: its size for the KLI chain and for piecewise SLERP, " +
    "which steps at the keys, and the chain's three parts.",
  "many.valuetext1": "smoothness 1",
  "many.figure2": "200 rotations of the swarm on the Hopf sphere",
  "many.figure3": "Measurements and their means on the Hopf sphere",
  "many.valuetext2": "20% wild",
  "many.figure4": "A graph of rotations, its edges coloured by how far each measurement disagrees with the answer",
  "many.valuetext3": "10% wrong",
  "clock.aria1": "The tour's time bar",
};

/** Three decimals etc. are page.js's; these put the numbers into words. */
export const live = {
  /** The heading of the exercises' answers, printed at the end of the handout. */
  answers: "Answers to the exercises",
  /** The turn's axis in a sentence. */
  axes: { x: "x", y: "y", z: "z", diagonal: "the diagonal (1, 1, 1)" },
  /** Each slider's value in words, beside it and for a screen reader (`aria-valuetext`). */
  values: {
    yaw: (/** @type {string} */ v) => `${v}° yaw`,
    pitch: (/** @type {string} */ v) => `${v}° pitch`,
    bank: (/** @type {string} */ v) => `${v}° bank`,
    angle: (/** @type {string} */ v, /** @type {string} */ axis) => `${v}° about ${axis}`,
    roll: (/** @type {string} */ v) => `${v}° roll about the nose`,
  },
  /** The other pages' figures' sliders in words (`aria-valuetext`). */
  figures: {
    smoothness: (/** @type {string} */ v) => `smoothness ${v}`,
    outliers: (/** @type {string} */ v) => `${v}% wild`,
    wrong: (/** @type {string} */ v) => `${v}% wrong`,
  },
  /** Section 9's turning rate: the chain's, with or without a jump (at smoothness 0). */
  rates: {
    jump: (/** @type {Record<string, string>} */ v) =>
      `At smoothness 0 the chain is piecewise SLERP: at k${v.key} ω jumps by ${v.jump} rad per unit time in an ` +
      `instant, an unbounded angular acceleration.`,
    smooth: (/** @type {Record<string, string>} */ v) =>
      `At smoothness ${v.s} ω has no jump at any key; its largest rate of change |ω̇| is ${v.acceleration} rad per ` +
      `unit time². Piecewise SLERP jumps by ${v.slerpJump} rad per unit time at k${v.slerpKey}.`,
  },
  slerp: (/** @type {Record<string, string>} */ v) => `At s = ${v.s} SLERP is ${v.slerp}° along the arc, NLERP ${v.nlerp}°.`,
  hopf: (/** @type {Record<string, string>} */ v) => `The nose points to ${v.nose}; a wing to ${v.wing}.`,
  drift: (/** @type {Record<string, string>} */ v) =>
    `The largest drift at h = ${v.h}: Euler ${v.euler}, RK4 ${v.rk4}, geodesic ${v.geodesic}.`,
  phases: (/** @type {Record<string, string>} */ v) => `At t = ${v.t}, R = ${v.order}.`,
  lohe: (/** @type {Record<string, string>} */ v) =>
    `At t = ${v.t}, R = ${v.order}; the farthest follower is a ${v.spread}° turn from r.`,
  kli: (/** @type {Record<string, string>} */ v) => `At t = ${v.t}, φ = ${v.phi}°, s = ${v.s}: q = ${v.q}.`,
  steps: (/** @type {Record<string, string>} */ v) =>
    `Step n = ${v.n} at t = ${v.t}: ‖r − q‖ = ${v.distance}. With ε = ${v.epsilon} and δ = ${v.delta} the loop stops ` +
    `after ${v.steps} steps, at T = ${v.T}; T* = ${v.predicted}.`,
  /** The time slider's value for a screen reader. */
  time: (/** @type {string} */ t, /** @type {string} */ end) => `t = ${t} of ${end}`,
  /** The canvases' text alternatives once the time rests. */
  labels: {
    phases: (/** @type {Record<string, string>} */ v) =>
      `Twenty Kuramoto phases on a circle at t = ${v.t}: order parameter R = ${v.order}.`,
    lohe: (/** @type {Record<string, string>} */ v) =>
      `Eight followers on S³ flowing to the pinned leader at t = ${v.t}: the farthest is ${v.spread}° from it.`,
    kli: (/** @type {Record<string, string>} */ v) =>
      `KLI on the great circle from p to r at t = ${v.t}: φ = ${v.phi}°, the velocity is the tangent part of r.`,
    clock: (/** @type {Record<string, string>} */ v) =>
      `KLI's progress along the arc against time: s = ${v.s} at t = ${v.t}, fast at first, then slow; SLERP's a straight line.`,
    steps: (/** @type {Record<string, string>} */ v) =>
      `Algorithm 1's distance to r at each step on a log scale, a straight fall; ${v.steps} steps, stopping at T = ${v.T}.`,
  },
  /** A saved video's title line. */
  video: "KLI: the paper's flow on the great circle, and its time warp",
  /** A value of the URL the module refused, by the control's key (the English page shows the module's own message;
   *  another language these): `got` is the value as the URL gave it. */
  refused: {
    axis: (/** @type {string} */ got) => `the axis must be x, y, z or diagonal (got ${got})`,
    integrator: (/** @type {string} */ got) => `the integrator must be euler, rk4 or geodesic (got ${got})`,
    digits: (/** @type {string} */ got) => `the digits of ε must be a whole number from 1 to 10 (got ${got})`,
    number: (/** @type {string} */ min, /** @type {string} */ max, /** @type {string} */ got) =>
      `must be a number from ${min} to ${max} (got ${got})`,
  },
};

/** The words the module draws on the figures (crates/kli-demo/src/learn/view.rs): `{name}` is filled in there. */
export const canvas = {
  yaw: "yaw",
  pitch: "pitch",
  bank: "bank",
  locked: "yaw and bank axes coincide: gimbal lock",
  apart: "yaw and bank axes {angle}° apart",
  axis: "axis",
  about: "{angle}° about {axis}",
  diagonal: "diagonal",
  turnedBy: "turned by q",
  turnedByMinus: "turned by −q",
  circle: "θ = {angle}°: q is {half}° round the circle",
  slerp: "s = {s}: SLERP {slerp}° along, NLERP {nlerp}° (of 60°)",
  wing: "wing",
  nose: "h(q): the nose",
  rolled: "rolled {angle}° about its nose",
  order: "R(t), the order parameter",
  pinned: "h(r), pinned",
  widest: "t = {t}   widest: {angle}° from r",
  along: "how far along the arc: s",
  steps: "‖r − qₙ‖ at each step",
  drift: "| |q| − 1 |, the drift off S³",
  largest: "{integrator}: largest drift {drift}",
  geodesic: "geodesic",
  rate: "|ω(t)|, the turning rate",
  parts: "ω(t) in its x, y, z parts",
  chain: "KLI chain, smoothness {smoothness}",
  pieces: "piecewise SLERP",
  jump: "jump {jump}",
};

/** The shared runtime's words on this page (its controls, the Save section, the navigation), by
 *  their English; `{name}` is a value filled in. English: each its own. */
export const runtime = {
  ...Object.fromEntries([
    // The time bar's buttons and the text size.
    "Play", "Pause", "Text size", "normal", "large (1.5×)", "projector (2×)", "hall (3×)",
    // Loading, and a value of the URL that its slider would refuse.
    "Loading the WebAssembly module…", "The WebAssembly module could not be loaded: {error}",
    "{key} must be from {min} to {max} on this page, as its slider (got {value})",
    // The pages' navigation.
    "Pages", "KLI: two rotations", "Many rotations", "The swarm", "Averaging", "Synchronising rotations",
    "Learn: a guided tour", "The mathematics", "For teachers", "With three.js",
    // The Save section: its title, each item's label and its name in a sentence (www/pages.js), what was saved.
    "Save", "{noun} as {format}", "Saved {what}.", "Could not save: {error}",
    "Euler angles", "the Euler angles figure", "Turn", "the turn", "Double cover", "the double cover",
    "SLERP", "the SLERP figure", "Hopf sphere", "the Hopf sphere", "Rolled object", "the rolled object",
    "Phases", "the Kuramoto phases", "Swarm on S³", "the swarm on S³", "KLI", "the KLI figure", "Time warp", "the time warp",
    "Algorithm 1", "Algorithm 1's steps", "Drift", "the drift", "Turning rate", "the turning rate", "Algorithm 1's path",
    // Saving a video (www/runtime/video/panel.js), the figures by their views' names.
    "Save a video",
    "Each frame drawn for its own time (not filmed from the screen): smooth on any machine. MP4 and WebM play in " +
      "PowerPoint, Keynote and Google Slides; GIF goes anywhere ({rate} frames a second).",
    "Format", "Size", "Frames a second", "From t =", "to t =", "Length, seconds", "Figures in the clip:", "Save video",
    "Cancel", "Video progress", "animated GIF", "{format} (this browser cannot encode it)",
    "Cannot save the video: {problem}.", "Encoding the video…", "Saved {name}: {frames} frames, {size} MB, encoded in {took} s.",
    "The video was cancelled.", "Could not save the video: {error}",
    "euler", "turn", "cover", "slerp", "hopf", "rolled", "phases", "lohe", "kli", "clock", "steps", "drift", "rates",
  ].map((english) => [english, english])),
};
