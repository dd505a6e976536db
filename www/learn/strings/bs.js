// @ts-check
// Tekst vodiča na bosanskom (learn.html?lang=bs): isti ključevi kao en.js (tests/js/learn-strings.test.mjs),
// isti markup, id-ovi i veze, prevedene samo riječi. Ijekavica, latinica; imena (SLERP, KLI, RK4, Lohe,
// Kuramoto, Hopf), formule i kod ostaju kakvi jesu; naslovi radova objavljenih na engleskom ostaju na
// engleskom (lang="en"), s prijevodom u zagradi gdje pomaže. Decimalna tačka kao u formulama i kodu.

/** Svaki dio članka, po ključu iz page.html. */
export const page = {
  "title": "Rotacije, od okreta do Kuramotovog toka — vodič kroz kli",
  "description": "Interaktivni vodič za studente: rotacije, kvaternioni, S³, SLERP, Hopfovo preslikavanje, Kuramotov model i KLI interpolacija Kapića i Crnkića, svaka ideja sa živom slikom i zadatkom.",
  "languages.aria": "Jezik",
  "header.h1": "Rotacije, od okreta do Kuramotovog toka",
  "header.p1":
    `Vodič za svakoga ko poznaje vektore i matrice, a još nije sreo kvaternion. Završava se metodom rada <a
    href="#paper"><span lang="en">“Interpolating Rotations with Non-abelian Kuramoto Model on the 3-Sphere”</span></a>
    (Interpolacija rotacija neabelovim Kuramotovim modelom na 3-sferi) autora Zinaida Kapića i Aladina Crnkića, koji
    ova stranica implementira. Svaka slika je živa: pomjeri njen klizač i tekst pored nje navodi nove vrijednosti.
    Slike koje se mijenjaju u vremenu dijele jedno vrijeme <var>t</var>, koje postavlja
    traka vremena na dnu ekrana. Svaki odjeljak završava pitanjem:
    predvidi odgovor, pa ga provjeri dugmetom u njemu.`,
  "contents.item1": `<a href="#care">Zašto je s rotacijama potreban oprez</a>`,
  "contents.item2": `<a href="#turn">Osa, ugao, četiri broja</a>`,
  "contents.item3": `<a href="#cover">S³ i dvostruko natkrivanje</a>`,
  "contents.item4": `<a href="#slerp">SLERP: veliki krug konstantnom brzinom</a>`,
  "contents.item5": `<a href="#hopf">Hopfovo preslikavanje i valjanje koje ne može pokazati</a>`,
  "contents.item6": `<a href="#kuramoto">Oscilatori koji se usklađuju</a>`,
  "contents.item7": `<a href="#kli">KLI: tok iz rada</a>`,
  "contents.item8": `<a href="#integrators">Integratori i odstupanje</a>`,
  "contents.item9": `<a href="#many">Mnogo rotacija</a>`,
  "contents.item10": `<a href="#glossary">Pojmovnik</a> · <a href="#paper">Literatura</a>`,
  "care.title1": `<span class="number">1</span> Zašto je s rotacijama potreban oprez`,
  "care.caption1":
    `Avion zaokrenut za tri ugla, s tri ose oko kojih se uglovi okreću: skretanje (plavo), propinjanje (zeleno),
    nagib (crveno, duž nosa).`,
  "care.p1":
    `Rotacija okreće svaki vektor oko ishodišta, čuvajući dužine i uglove. Na kursu o matricama uvodi se kao 3 × 3
    <em>matrica rotacije</em> <var>R</var>: njene kolone su slike triju osa, a <var>R</var>ᵀ<var>R</var> =
    <var>I</var>, det <var>R</var> = 1. To je devet brojeva povezanih sa šest jednačina, za samo tri stepena slobode.
    Pomnoži ih nekoliko hiljada u aritmetici s pokretnim zarezom i zaokruživanje polako narušava jednačine; uzmi
    prosjek dvije takve matrice element po element i rezultat uopšte nije rotacija: na pola puta između <var>I</var>
    i poluokreta oko <var>z</var> je diag(0, 0, 1), koja cijeli prostor spljošti na osu <var>z</var> (determinanta joj je 0).`,
  "care.p2":
    `Onda tri broja? <dfn id="def-euler">Eulerovi uglovi</dfn> okreću oko <var>z</var> za skretanje, zatim oko nove
    ose <var>y</var> za propinjanje, pa oko nove ose <var>x</var> (nosa) za nagib (piloti ovaj ugao zovu i valjanje;
    ovaj vodič ga zove nagib, a „valjanje” čuva za dodatni okret oko nosa u odjeljku 5): <var>R</var> = <var>R<sub>z</sub></var>(skretanje)
    <var>R<sub>y</sub></var>(propinjanje) <var>R<sub>x</sub></var>(nagib). (Čitan zdesna nalijevo, kako matrice
    djeluju na vektor, isti proizvod okreće oko nepomičnih osa svijeta obrnutim redom: nagib oko <var>x</var>, zatim
    propinjanje oko <var>y</var>, pa skretanje oko <var>z</var>. Oba čitanja daju isto <var>R</var>.) Pomjeri klizač propinjanja ispod prema 90° i
    gledaj kako se osa skretanja i osa nagiba približavaju. Na 90° one su jedna prava: skretanje i nagib sada rade
    isto i jedan stepen slobode je izgubljen. To je <dfn id="def-gimbal">blokada kardana</dfn> (engl. gimbal lock; kardan (kardanski ovjes) je sklop ugniježđenih
    prstenova koji drži kompas ili kameru, a svaki se prsten okreće oko jedne ose), i
    svaki izbor tri ugla negdje naiđe na nju.`,
  "care.legend1": "Eulerovi uglovi",
  "care.p3":
    `Sada su osa skretanja i osa nagiba razmaknute <output id="lock-out">50.0°</output> (ugao je 90° − |propinjanje|).`,
  "care.p4":
    `Šta bismo htjeli umjesto toga: malo brojeva, jedan jednostavan uslov, bez blokade, proizvod za izvođenje jednog
    okreta za drugim i čist način da se ide <em>između</em> dvije rotacije. Kvaternioni daju sve to, i zato su ih
    preuzeli simulatori letenja i računarska grafika, kako rad podsjeća u svom uvodu.`,
  "exercise.answer": "Prikaži odgovor",
  "care.question1": "Predvidi, pa provjeri: pri propinjanju od 90°, šta rade skretanje i nagib?",
  "care.p5":
    `Prvo pogodi. Zatim <a class="set" href="?pitch=90#care" data-state='{"pitch":90}'>postavi propinjanje na 90°</a>
    i pomjeraj klizače skretanja i nagiba jedan za drugim.`,
  "care.p6":
    `<strong>Odgovor.</strong> Oba okreću avion oko iste vertikalne prave, a tekst pokazuje razmak od 0°. S nosom
    usmjerenim pravo dolje (propinjanje od 90° prevodi <var>x</var> u −<var>z</var>; kad je <var>z</var> gore, pozitivno propinjanje
    ovdje spušta nos), osa nagiba je osa skretanja,
    pa se ta dva ugla računaju samo zajedno: bitna je razlika skretanja i nagiba. Nijedna mala promjena tri ugla ne
    okreće nos u stranu.`,
  "turn.title1": `<span class="number">2</span> Osa, ugao, četiri broja`,
  "turn.p1":
    `Euler je pokazao da je svaka rotacija jedan okret za ugao <var>θ</var> oko ose, jediničnog vektora <var>u</var>.
    <dfn id="def-quaternion">Kvaternion</dfn> je broj <var>q</var> = <var>a</var> + <var>b</var> i + <var>c</var> j
    + <var>d</var> k s četiri realna dijela, gdje Hamiltonova pravila i² = j² = k² = ijk = −1 određuju kako se
    množi. Redoslijed je bitan: ij = k, jk = i, ki = j, ali ji = −k, kj = −i, ik = −j. Njegova dužina je |<var>q</var>| = √(<var>a</var>² +
    <var>b</var>² + <var>c</var>² + <var>d</var>²), njegov konjugovani kvaternion je <var>q̄</var> = <var>a</var> −
    <var>b</var> i − <var>c</var> j − <var>d</var> k, a <dfn id="def-unit-quaternion">jedinični kvaternion</dfn> je
    kvaternion dužine 1.`,
  "turn.p2":
    `Proizvodi se najbrže računaju pomoću vektora. Zapiši kvaternion kao zbir realnog i vektorskog dijela,
    <var>a</var> + <var>m</var>, gdje je <var>m</var> = <var>b</var> i + <var>c</var> j + <var>d</var> k, a
    jedinice i, j i k čitaj kao jedinične vektore duž <var>x</var>, <var>y</var> i <var>z</var>. Realni brojevi
    komutiraju s jedinicama i, j i k, a gornja pravila daju (<var>s</var> + <var>m</var>)(<var>t</var> +
    <var>n</var>) = (<var>s</var><var>t</var> − <var>m</var>·<var>n</var>) + (<var>s</var><var>n</var> +
    <var>t</var><var>m</var> + <var>m</var> × <var>n</var>), uz skalarni i vektorski proizvod u R³: izmnoži
    <var>m</var><var>n</var> član po član, pa kvadrati (i² = j² = k² = −1) daju −<var>m</var>·<var>n</var>, a
    proizvodi različitih jedinica (ij = k, ji = −k, …) daju <var>m</var> × <var>n</var> (probaj <var>m</var> =
    i, <var>n</var> = j: 0 + i × j = k). Kao i množenje matrica, ovo množenje je asocijativno,
    (<var>p</var><var>q</var>)<var>r</var> = <var>p</var>(<var>q</var><var>r</var>), ali nije komutativno. Iz
    toga slijede tri činjenice koje se koriste kroz cijeli vodič. Prvo, <var>q</var><var>q̄</var> =
    <var>q̄</var><var>q</var> = |<var>q</var>|², pa kod jediničnog kvaterniona <var>q̄</var> poništava
    <var>q</var>. Drugo, konjugovani kvaternion proizvoda je proizvod konjugovanih kvaterniona obrnutim redom:
    <var>q̄</var><var>p̄</var> za <var>p</var><var>q</var>, jer je <var>m</var> × <var>n</var> = −<var>n</var> ×
    <var>m</var>. Treće, za <var>p</var> = <var>a</var> + <var>b</var> i + <var>c</var> j + <var>d</var> k i
    <var>r</var> = <var>a′</var> + <var>b′</var> i + <var>c′</var> j + <var>d′</var> k, realni dio proizvoda
    <var>r</var><var>p̄</var> je <var>a</var><var>a′</var> + <var>b</var><var>b′</var> +
    <var>c</var><var>c′</var> + <var>d</var><var>d′</var>: to je skalarni proizvod kvaterniona <var>p</var> i
    <var>r</var> kada ih posmatramo kao vektore u R⁴; u odjeljku 3 ga pišemo kao <var>p</var>·<var>r</var>.`,
  "turn.p3": "Okret za <var>θ</var> oko <var>u</var> je jedinični kvaternion",
  "turn.p4":
    `<var>q</var> = cos(<var>θ</var>/2) + sin(<var>θ</var>/2) (<var>u<sub>x</sub></var> i + <var>u<sub>y</sub></var>
    j + <var>u<sub>z</sub></var> k),`,
  "turn.p5":
    `i on vektor <var>v</var>, zapisan kao <var>v<sub>x</sub></var> i + <var>v<sub>y</sub></var> j +
    <var>v<sub>z</sub></var> k, prevodi u <var>q</var> <var>v</var> <var>q̄</var>. Provjeri to na prvom okretu
    sa slike, 90° oko <var>z</var>: <var>q</var> = (1 + k)/√2, a <var>q̄</var> = (1 − k)/√2. Tada je
    <var>q</var> i = (i + ki)/√2 = (i + j)/√2, a (i + j)(1 − k)/2 = (i − ik + j − jk)/2 = (i + j + j − i)/2 = j:
    nos, <var>x</var>, ide u <var>y</var>, četvrtina punog okreta. Pogledaj stanje na pola puta: <var>q</var> i
    = (i + j)/√2 je vektor i već okrenut za 45° oko <var>z</var>, a množenje s <var>q̄</var> zdesna okreće ga za
    preostalih 45°. Vektor okomit na osu svaki činilac okreće za <var>θ</var>/2, i zato <var>q</var> sadrži
    polovinu ugla; vektor duž ose par činilaca zajedno ne mijenja, iako ga svaki činilac sam mijenja:
    <var>q</var> k <var>q̄</var> = k. Svaki vektor je zbir dijela duž ose i dijela okomitog na nju, a
    preslikavanje <var>v</var> ↦ <var>q</var> <var>v</var> <var>q̄</var> je linearno, pa ova dva slučaja
    pokrivaju svaki vektor; rezultat nema realnog dijela, jer je po drugoj činjenici njegov konjugovani
    kvaternion <var>q</var> <var>v̄</var> <var>q̄</var> = −<var>q</var> <var>v</var> <var>q̄</var>, pa je opet
    vektor. Dva okreta jedan za drugim daju proizvod: <var>q</var>₂<var>q</var>₁ prvo okreće za <var>q</var>₁,
    jer je zbog asocijativnosti <var>q</var>₂(<var>q</var>₁ <var>v</var> <var>q̄</var>₁)<var>q̄</var>₂ =
    (<var>q</var>₂<var>q</var>₁) <var>v</var> (<var>q̄</var>₁<var>q̄</var>₂), a <var>q̄</var>₁<var>q̄</var>₂ je
    po drugoj činjenici konjugovani kvaternion proizvoda <var>q</var>₂<var>q</var>₁. Četiri broja i jedan uslov,
    |<var>q</var>| = 1, a ako ga zaokruživanje pokvari, dijeljenje <var>q</var> sa |<var>q</var>| ga ponovo
    uspostavlja.`,
  "turn.caption1":
    `Avion zaokrenut za <var>q</var>. Isprekidana linija je osa okreta, nepomična u svijetu. Obojene strelice su ose
    tijela aviona, koje se okreću zajedno s njim: <span class="x">x</span> (nos), <span class="y">y</span> (krilo),
    <span class="z">z</span> (vertikalni stabilizator). Prije okreta leže duž osa svijeta <var>x</var>, <var>y</var> i
    <var>z</var>, pa nakon njega svaka pokazuje kuda <var>q</var> šalje tu osu svijeta.`,
  "turn.legend1": "Okret",
  "turn.p6":
    `Četiri broja sada: <output id="turn-out">q = 0.707 + 0.000 i + 0.000 j + 0.707 k</output>.`,
  "turn.question1":
    `Predvidi, pa provjeri: okret za 120° oko dijagonale (1, 1, 1)/√3. Koja su četiri broja i kamo ide nos?`,
  "turn.p7":
    `Prvo to izračunaj iz formule. Zatim <a class="set" href="?axis=diagonal&amp;angle=120#turn"
    data-state='{"axis":"diagonal","angle":120}'>postavi 120° oko dijagonale</a>.`,
  "turn.p8":
    `<strong>Odgovor.</strong> cos 60° = 0.5, sin 60° = 0.866, a svaka komponenta ose je 1/√3 = 0.577, pa svaka od
    jedinica i, j, k dobija 0.866 × 0.577 = 0.5: <var>q</var> = 0.5 + 0.5 i + 0.5 j + 0.5 k, što je rotacija <var>r</var>
    iz primjera u radu, koju ponovo srećemo u odjeljku 4. Trećina punog okreta oko dijagonale kružno premješta ose: nos, osa <var>x</var>, ide u
    <var>y</var> (<var>q</var> i <var>q̄</var> = j), <var>y</var> ide u <var>z</var>, a <var>z</var> u
    <var>x</var>.`,
  "cover.title1": `<span class="number">3</span> S³ i dvostruko natkrivanje`,
  "cover.p1":
    `Četiri broja jediničnog kvaterniona su tačka na udaljenosti 1 od ishodišta četverodimenzionalnog prostora:
    jedinični kvaternioni čine <dfn id="def-s3">3-sferu, S³</dfn>, trodimenzionalnu površ u R⁴, kao što je obična
    sfera S² dvodimenzionalna površ u R³. Ne možemo je nacrtati cijelu, ali možemo nacrtati jedan presjek: kako
    <var>θ</var> raste, <var>q</var> = cos(<var>θ</var>/2) + sin(<var>θ</var>/2) <var>u</var> kruži po kružnici kroz
    1 i <var>u</var>, dvostruko sporije od okreta.`,
  "cover.p2":
    `Pritisni 360° ispod. Avion je opet tamo gdje je počeo, a ipak je <var>q</var> = −1 na suprotnoj strani kružnice.
    Budući da je (−<var>q</var>) <var>v</var> (−<var>q̄</var>) = <var>q</var> <var>v</var> <var>q̄</var>, kvaternioni
    <var>q</var> i −<var>q</var> su jedna ista rotacija: svaka rotacija je par suprotnih tačaka sfere S³. To je
    <dfn id="def-double-cover">dvostruko natkrivanje</dfn>, i metoda na rotacijama mora ili zanemariti predznak ili
    reći koji uzima.`,
  "cover.p3":
    `Posmatraj svaki jedinični kvaternion <var>a</var> + <var>b</var> i + <var>c</var> j + <var>d</var> k kao vektor
    (<var>a</var>, <var>b</var>, <var>c</var>, <var>d</var>) u R⁴. Za dva takva kvaterniona, <var>p</var> i
    <var>r</var>, ugao <var>φ</var> između njih je uobičajeni ugao, koji se dobija iz skalarnog proizvoda ta dva
    četverodimenzionalna vektora: cos <var>φ</var> = <var>p</var>·<var>r</var>. On mjeri koliko su rotacije
    udaljene jedna od druge.`,
  "cover.p4":
    `Kolika je ta udaljenost izražena kao okret? Okret koji prevodi <var>p</var> u <var>r</var> je <var>r</var>
    <var>p̄</var>, jer je (<var>r</var> <var>p̄</var>) <var>p</var> = <var>r</var> (<var>p̄</var> <var>p</var>) =
    <var>r</var>, a prema odjeljku 2 njegov realni dio je <var>p</var>·<var>r</var> = cos <var>φ</var>. Realni dio
    cos(<var>θ</var>/2) odgovara okretu za <var>θ</var> (opet odjeljak 2: jedinični kvaternion s realnim dijelom
    cos(<var>θ</var>/2), za <var>θ</var> od 0° do 360°, ima vektorski dio dužine sin(<var>θ</var>/2), jer je <var>a</var>² + |<var>m</var>|² = 1, pa je
    to cos(<var>θ</var>/2) + sin(<var>θ</var>/2) <var>u</var>, gdje je <var>u</var> jedinični vektor duž njegovog
    vektorskog dijela), pa rotacija od <var>p</var> do <var>r</var> okreće za
    2<var>φ</var>: uglovi na S³ su polovine uglova okreta. (Kad je <var>p</var>·<var>r</var> &lt; 0, ugao
    2<var>φ</var> je veći od 180°, a ista rotacija je okret za 360° − 2<var>φ</var> u suprotnom smjeru.)`,
  "cover.p5":
    `Najkraći put po sferi je luk velikog kruga (presjeka sfere i ravni kroz njen centar), <dfn
    id="def-geodesic">geodezijska linija</dfn>. Između dvije rotacije postoje dva takva luka, do <var>r</var> i do
    −<var>r</var>; „najkraći put” bira onaj za koji je <var>p</var>·<var>r</var> ≥ 0. <a href="#kli">KLI</a>, metoda
    iz rada (odjeljak 7), ne bira: kad je <var>p</var>·<var>r</var> &lt; 0, teče dužim putem, pa zato prvo treba
    promijeniti predznak kvaterniona <var>r</var>, tako da bude <var>p</var>·<var>r</var> ≥ 0.`,
  "cover.caption1":
    `Lijevo (gore, na uskom ekranu): kružnica na S³ kroz 1 i osu <var>u</var>, luk od 1 do <var>q</var> i
    −<var>q</var> nasuprot. Desno (dolje): avion zaokrenut za <var>q</var> i za −<var>q</var>.`,
  "cover.p6":
    `Pri <output id="cover-out">θ = 90°, q = 0.707 + 0.000 i + 0.000 j + 0.707 k</output> (pomjera ga i klizač ugla
    iz odjeljka 2).`,
  "cover.question1": "Predvidi, pa provjeri: koliko se avion mora okrenuti da bi q opet bio 1?",
  "cover.p7":
    `Pogodi, pa <a class="set" href="?angle=720#cover" data-state='{"angle":720}'>postavi θ = 720°</a>.`,
  "cover.p8":
    `<strong>Odgovor.</strong> Dva puna okreta. Nakon jednog okreta <var>q</var> = −1: ista rotacija, druga tačka.
    Tek na 720° <var>q</var> jednom obiđe svoju kružnicu.`,
  "slerp.title1": `<span class="number">4</span> SLERP: veliki krug konstantnom brzinom`,
  "slerp.p1":
    `Da bismo animirali okret od rotacije <var>p</var> do rotacije <var>r</var>, treba nam put
    <var>q</var>(<var>s</var>), <var>s</var> od 0 do 1. Duž (1 − <var>s</var>)<var>p</var> +
    <var>s</var><var>r</var> presijeca unutrašnjost sfere; kad se njene tačke vrate na sferu (<abbr
    title="normalizovana linearna interpolacija">NLERP</abbr>, normalizovana linearna interpolacija: tačka duži
    podijeljena svojom dužinom), padaju na pravi luk, ali neravnomjerno, brže u sredini. <dfn
    id="def-slerp">SLERP</dfn>, sferna linearna interpolacija (Shoemake, 1985), ide po velikom krugu konstantnom
    brzinom:`,
  "slerp.p2":
    `<var>q</var>(<var>s</var>) = [sin((1 − <var>s</var>)<var>φ</var>₀) <var>p</var> + sin(<var>s</var><var>φ</var>₀)
    <var>r</var>] / sin <var>φ</var>₀, cos <var>φ</var>₀ = <var>p</var>·<var>r</var>.`,
  "slerp.p3":
    `Njegova tačka je <var>s</var><var>φ</var>₀ duž luka. Ekvivalentno, <var>q</var>(<var>s</var>) = <var>w</var>
    <var>p</var>, gdje je <var>w</var> okret za 2<var>s</var><var>φ</var>₀ oko ose kvaterniona <var>r</var> <var>p̄</var>
    (okret iz odjeljka 3 od <var>p</var> do <var>r</var>, za 2<var>φ</var>₀), postepeno izveden do udjela
    <var>s</var>: zato se tijelo okreće oko te jedne nepomične ose ujednačenom brzinom. Ispod su dvije rotacije iz rada, <var>p</var> = k, poluokret oko <var>z</var> (θ = 180°, jer je cos 90°
    + sin 90° k = k), i <var>r</var> = ½(1 + i + j + k), trećina okreta (120°) oko dijagonale (1, 1, 1):
    <var>p</var>·<var>r</var> = ½, pa je <var>φ</var>₀ = 60° na S³, okret tijela za 120°. Ponovo ih srećemo u
    odjeljku 7.`,
  "slerp.caption1":
    `Luk od <var>p</var> do <var>r</var>; oznake na svakih 0.1 od <var>s</var>, <span class="slerp">SLERP</span>-ove
    spolja, NLERP-ove unutra; tetiva, duž od <var>p</var> do <var>r</var>, isprekidano.`,
  "slerp.legend1": "SLERP",
  "slerp.p4": `<output id="slerp-out">Pri s = 0.50 SLERP je 30.00° duž luka, NLERP 30.00°.</output>`,
  "slerp.question1": "Predvidi, pa provjeri: pri s = 0.25, je li NLERP ispred SLERP-a ili iza njega?",
  "slerp.p5": `Pogodi, pa <a class="set" href="?s=0.25#slerp" data-state='{"s":0.25}'>postavi s = 0.25</a>.`,
  "slerp.p6":
    `<strong>Odgovor.</strong> Iza: 13.90° naspram 15° kod SLERP-a. Tačka tetive na četvrtini puta je (0.75 + 0.25
    cos 60°, 0.25 sin 60°) u ravni luka, pod uglom atan(0.2165 / 0.875) = 13.90°. Zbog simetrije je ispred nakon
    sredine (46.10° pri <var>s</var> = 0.75).`,
  "hopf.title1": `<span class="number">5</span> Hopfovo preslikavanje i valjanje koje ne može pokazati`,
  "hopf.p1":
    `S³ ne stane na papir, pa rad crta svoje krive na običnoj sferi pomoću <dfn id="def-hopf">Hopfovog
    preslikavanja</dfn> (jednačina 5 u radu):`,
  "hopf.p2":
    `<var>h</var>(<var>a</var>, <var>b</var>, <var>c</var>, <var>d</var>) = (<var>a</var>² + <var>b</var>² −
    <var>c</var>² − <var>d</var>², 2(<var>a</var><var>d</var> + <var>b</var><var>c</var>),
    2(<var>b</var><var>d</var> − <var>a</var><var>c</var>)) <span class="eq-no">(5)</span>`,
  "hopf.p3":
    `To je <var>q</var> i <var>q̄</var>: kamo rotacija šalje osu <var>x</var>, nos aviona. Tačka na S² pokazuje kamo
    je nos usmjeren, i <var>h</var>(<var>q</var>) = <var>h</var>(−<var>q</var>). Za primjer iz rada je
    <var>h</var>(<var>p</var>) = (−1, 0, 0) i <var>h</var>(<var>r</var>) = (0, 1, 0).`,
  "hopf.p4":
    `Ono što ne može pokazati je valjanje oko nosa. Ovdje je valjanje <var>ρ</var> novi okret dodan okretu <var>q</var>
    iz odjeljka 2. Okreće oko nosa, kao nagib iz odjeljka 1, ali se dodaje povrh okreta <var>q</var> umjesto da
    bude jedan od tri ugla. Okreni avion oko
    nosa klizačem ispod: krilo se okreće, tačka ostaje. Zaokrenuta rotacija je <var>q</var> (cos(<var>ρ</var>/2) +
    sin(<var>ρ</var>/2) i), i može se čitati na dva načina. Po pravilu iz odjeljka 2 (desni činilac okreće prvi),
    ona se prvo valja oko ose <var>x</var> svijeta, gdje nos počinje, pa se okreće za <var>q</var>. Ili se prvo okreće
    za <var>q</var>, pa se valja oko vlastitog nosa aviona, gdje god ga je <var>q</var> postavio. Oba čitanja daju istu
    rotaciju. Svaka rotacija ovog oblika ima istu sliku, pa iznad
    svake tačke sfere S² leži cijela kružnica sfere S³, njeno <dfn id="def-fibre">vlakno</dfn>. Sfera vjerno
    prikazuje kamo su stvari usmjerene, a slijepa je za to kako su zaokrenute oko tog pravca.`,
  "hopf.caption1":
    `Tačka nosa <var>h</var>(<var>q</var>) (narandžasto) i tačka krila (zeleno) na kružnici pravaca okomitih na nos
    (okomit znači pod pravim uglom; za vektore, skalarni proizvod jednak 0). Povuci mišem ili koristi tipke sa
    strelicama da okreneš sferu.`,
  "hopf.caption2": "Okret iz odjeljka 2, zatim valjanje oko nosa.",
  "hopf.legend1": "Valjanje",
  "hopf.p5":
    `<output id="hopf-out">Nos pokazuje prema (0.000, 1.000, 0.000); krilo prema (−1.000, 0.000, 0.000).</output>`,
  "hopf.question1": "Predvidi, pa provjeri: valjanje od 180°. Kamo ide tačka?",
  "hopf.p6":
    `Pogodi, pa <a class="set" href="?roll=180#hopf" data-state='{"roll":180}'>postavi valjanje na 180°</a>.`,
  "hopf.p7":
    `<strong>Odgovor.</strong> Nikamo. Krilo sada pokazuje na suprotnu stranu, ali nos se nije pomaknuo, a tačka je
    nos. Obje rotacije leže na istom vlaknu.`,
  "kuramoto.title1": `<span class="number">6</span> Oscilatori koji se usklađuju`,
  "kuramoto.p1":
    `Krijesnice bljeskaju zajedno, ćelije predvodnika srčanog ritma kucaju zajedno. <dfn id="def-kuramoto">Kuramotov
    model</dfn> (Kuramoto, 1975) je najjednostavniji opis: <var>N</var> oscilatora s fazama <var>θ<sub>i</sub></var>
    na kružnici, svaki sa svojom vlastitom frekvencijom <var>ω<sub>i</sub></var>, svaki privlačen prema ostalima. Faza je ugao
    koji kaže gdje je oscilator u svom ciklusu; vlastita frekvencija je brzina kojom taj ugao raste kad
    ga ništa ne privlači. U jednačini ispod prim (′) označava brzinu promjene u vremenu, <var>θ</var>′ =
    d<var>θ</var>/d<var>t</var>, a zbir ide po svim <var>j</var>:`,
  "kuramoto.p2":
    `<var>θ<sub>i</sub></var>′ = <var>ω<sub>i</sub></var> + (<var>K</var>/<var>N</var>) Σ<sub><var>j</var></sub>
    sin(<var>θ<sub>j</sub></var> − <var>θ<sub>i</sub></var>).`,
  "kuramoto.p3":
    `Koliko se slažu, mjeri <dfn id="def-order">parametar reda</dfn>: dužina <var>R</var> njihove prosječne tačke,
    (1/<var>N</var>) Σ e<sup>i<var>θ<sub>j</sub></var></sup>; 0 kad su raštrkani, 1 kad su usklađeni (s različitim vlastitim frekvencijama ustali se malo ispod 1: brži
    ostaju malo ispred).
    Ovdje je i imaginarna jedinica kompleksnih brojeva, i² = −1, a e<sup>i<var>θ</var></sup> = cos <var>θ</var> + i
    sin <var>θ</var> je tačka pod uglom <var>θ</var> na jediničnoj kružnici kompleksne ravni. To nije komponenta i
    kvaterniona iz odjeljka 2: kvaternion ima tri takve jedinice, i, j i k, a na S³ niže se usrednjavaju sami
    kvaternioni. Ispod, 20 faza
    ima frekvencije ravnomjerno raspoređene od −0.5 do 0.5 (narandžaste se okreću naprijed, ljubičaste unazad). Za
    mnogo oscilatora s takvom raspodjelom privlačenje pobjeđuje čim <var>K</var> pređe 2/(π<var>g</var>(0)) ≈ 0.64,
    gdje je <var>g</var>(0) = 1 gustina frekvencija u njihovom središtu. Blizu te vrijednosti okupljanje je sporo:
    na ovoj slici, u 12 jedinica vremena i s 20 faza koje počinju gotovo raštrkane, jasno se vidi tek od otprilike
    <var>K</var> = 1.2. Postavi <var>K</var> i pritisni
    <strong>Pusti od t = 0</strong>.`,
  "kuramoto.caption1":
    `Faze na svojoj kružnici, strelica je njihova prosječna tačka; pored je <var>R</var>(<var>t</var>) do kraja trake
    vremena, s označenim prikazanim trenutkom.`,
  "kuramoto.legend1": "Kuramotove faze",
  "kuramoto.p4": `<output id="phases-out">Pri t = 0.00, R = 0.049.</output>`,
  "kuramoto.p5":
    `Sabiranju uglova redoslijed nije bitan, pa se ovaj model zove <em>abelov</em>. Rotacijama jeste bitan: na S³
    proizvod kvaterniona nije komutativan. M. A. Lohe, koji je Kuramotov model uopštio s faza na matrice (2009),
    nazvao je takve modele <em>neabelovim</em> Kuramotovim modelima. Na S³ oscilatori su jedinični kvaternioni
    <var>q<sub>i</sub></var> (jednačina 1 u radu je opšti oblik modela, u kojem se svaki oscilator može i sam okretati, kao
    <var>ω<sub>i</sub></var> iznad). Kad svaki privlači svakog, bez vlastite rotacije,
    svaki slijedi`,
  "kuramoto.p6":
    `<var>q<sub>i</sub></var>′ = (<var>K</var>/(2<var>N</var>)) Σ<sub><var>j</var></sub> (<var>q<sub>j</sub></var> −
    <var>q<sub>i</sub></var> <var>q̄<sub>j</sub></var> <var>q<sub>i</sub></var>),`,
  "kuramoto.p7":
    `gdje je <var>q<sub>i</sub></var> <var>q̄<sub>j</sub></var> <var>q<sub>i</sub></var> proizvod kvaterniona, u
    kojem je redoslijed faktora bitan. Za jedinične kvaternione on je jednak
    2(<var>q<sub>i</sub></var>·<var>q<sub>j</sub></var>)<var>q<sub>i</sub></var> − <var>q<sub>j</sub></var>
    (odjeljak 7 koristi isti identitet), pa je svaki sabirak 2(<var>q<sub>j</sub></var> −
    (<var>q<sub>i</sub></var>·<var>q<sub>j</sub></var>) <var>q<sub>i</sub></var>): privlačenje prema svakom od
    ostalih oscilatora, iz kojeg je uklonjen dio duž <var>q<sub>i</sub></var>.`,
  "kuramoto.p11":
    `Provjera na kružnici: na njoj se ova jednačina svodi na gornju jednačinu faza sa svim
    <var>ω<sub>i</sub></var> = 0. Stavi <var>z<sub>i</sub></var> = e<sup>i<var>θ<sub>i</sub></var></sup> umjesto
    <var>q<sub>i</sub></var>; tada je <var>z<sub>j</sub></var> − <var>z<sub>i</sub></var>
    <var>z̄<sub>j</sub></var> <var>z<sub>i</sub></var> = 2i sin(<var>θ<sub>j</sub></var> −
    <var>θ<sub>i</sub></var>) <var>z<sub>i</sub></var>, a <var>z<sub>i</sub></var>′ = i<var>θ<sub>i</sub></var>′
    <var>z<sub>i</sub></var>, pa je <var>θ<sub>i</sub></var>′ = (<var>K</var>/<var>N</var>)
    Σ<sub><var>j</var></sub> sin(<var>θ<sub>j</sub></var> − <var>θ<sub>i</sub></var>).`,
  "kuramoto.p12":
    `Sada fiksiraj jedan od njih u rotaciji <var>r</var>, tako da se nikad ne pomjera: to je <dfn
    id="def-leader">vođa</dfn>, a ostali, <em>sljedbenici</em>, najprije se usklade i zatim smire u njegovom
    položaju. S jednim sljedbenikom, <var>N</var> = 2 (sabirak za <var>j</var> = <var>i</var> jednak je 0), za
    sljedbenika vrijedi <var>q</var>′ = (<var>K</var>/2)(<var>r</var> − (<var>q</var>·<var>r</var>)
    <var>q</var>): to je metoda iz rada (tačno pri <var>K</var> = 2; uz drugi <var>K</var> put je isti, samo se
    prelazi po satu koji ide <var>K</var>/2 puta brže), o kojoj je riječ u sljedećem odjeljku.`,
  "kuramoto.p13":
    `Koliko se slažu, mjeri se kao na kružnici: parametar reda na S³ je dužina <var>R</var> = |(1/<var>N</var>)
    Σ<sub><var>j</var></sub> <var>q<sub>j</sub></var>| srednje vrijednosti kvaterniona <var>q<sub>j</sub></var>
    kao tačaka u R⁴ (računajući i vođu); jednak je 1 kad su svi u jednoj tački, a mali kad su raspršeni po S³.
    Osjetljiv je na predznak: <var>q</var> i −<var>q</var> u prosjeku daju 0, pa <var>R</var> može biti mali
    iako se rotacije slažu.`,
  "kuramoto.caption2":
    `Osam sljedbenika (ljubičasto, sa svojim tragovima) i fiksirani vođa <var>r</var> (narandžasto), nacrtani
    Hopfovim preslikavanjem; sfera se okreće zajedno s onom u odjeljku 5.`,
  "kuramoto.legend2": "Rotacije na S³",
  "kuramoto.p8":
    `<output id="lohe-out">Pri t = 0.00, R = 0.396; najdalji sljedbenik je okret od 174.5° od r.</output>`,
  "kuramoto.question1": "Predvidi, pa provjeri: bez sprezanja, K = 0, šta radi R?",
  "kuramoto.p9":
    `Pogodi, pa <a class="set" href="?K=0&amp;K3=0#kuramoto" data-state='{"coupling":0,"lohe":0}' data-play="phases">postavi K = 0 i
    pusti</a>.`,
  "kuramoto.p10":
    `<strong>Odgovor.</strong> Svaka faza se okreće svojom brzinom, <var>θ<sub>i</sub></var>(<var>t</var>) =
    <var>θ<sub>i</sub></var>(0) + <var>ω<sub>i</sub></var><var>t</var>, i ništa ih ne okuplja: <var>R</var> luta
    blizu 0. Na S³ s <var>K</var> = 0 ništa se uopšte ne kreće, jer je <var>q<sub>i</sub></var>′ = 0.`,
  "kli.title1": `<span class="number">7</span> KLI: tok iz rada`,
  "kli.p1":
    `<dfn id="def-kli">KLI</dfn>, Kuramoto–Lohe interpolacija, metoda koju su dali <a href="#paper">Kapić i
    Crnkić</a>, pušta rotaciju da teče od <var>p</var> do <var>r</var> po modelu (jednačina 3 u radu)`,
  "kli.p2":
    `<var>q</var>′(<var>t</var>) = −½ (<var>q</var> <var>r̄</var> <var>q</var> − <var>r</var>), <var>q</var>(0) =
    <var>p</var>. <span class="eq-no">(3)</span>`,
  "kli.p3":
    `Za jedinični <var>q</var> je <var>q</var> <var>r̄</var> <var>q</var> = 2(<var>q</var>·<var>r</var>)<var>q</var>
    − <var>r</var>, pa je ovo jednostavno <var>q</var>′ = <var>r</var> − (<var>q</var>·<var>r</var>) <var>q</var>.
    (Zašto: <var>q</var> <var>r̄</var> i <var>r</var> <var>q̄</var> su međusobno konjugovani, pa je njihov zbir
    jednak dvostrukom realnom dijelu, <var>q</var> <var>r̄</var> + <var>r</var> <var>q̄</var> = 2(<var>q</var>·<var>r</var>);
    pomnoži zdesna sa <var>q</var> i iskoristi <var>q̄</var> <var>q</var> = 1.) Slika pokazuje zašto to funkcioniše. (<var>q</var>·<var>r</var>)<var>q</var> je dio vektora <var>r</var> duž
    <var>q</var>; ostatak je okomit na <var>q</var>, tangenta sfere. Brzina okomita na <var>q</var> čuva
    |<var>q</var>| = 1, jer je d|<var>q</var>|²/d<var>t</var> = 2 <var>q</var>·<var>q</var>′ = 0. I leži u ravni
    vektora <var>q</var> i <var>r</var>, pa <var>q</var> nikad ne napušta veliki krug kroz <var>p</var> i
    <var>r</var>: luk SLERP-a.`,
  "kli.caption1":
    `Veliki krug kroz <var>p</var> i <var>r</var> (luk SLERP-a isprekidano), dosadašnji put <span
    class="kli">KLI</span>-ja i u <var>q</var>(<var>t</var>) njegova brzina <var>q</var>′, tangentni dio vektora
    <var>r</var>.`,
  "kli.p4":
    `<output id="kli-out">Pri t = 0.00, φ = 60.00°, s = 0.000: q = 0.000 + 0.000 i + 0.000 j + 1.000 k.</output>`,
  "kli.p5":
    `<strong>Iskrivljenje vremena.</strong> Neka je <var>φ</var>(<var>t</var>) ugao između <var>q</var>(<var>t</var>) i <var>r</var>.
    Tada je cos <var>φ</var> = <var>q</var>·<var>r</var>, a njegova brzina
    promjene je <var>q</var>′·<var>r</var> = 1 − (<var>q</var>·<var>r</var>)² = sin²<var>φ</var>. Ona je također
    −sin <var>φ</var> · <var>φ</var>′, pa je <var>φ</var>′ = −sin <var>φ</var>. Promjenljive se razdvajaju, a ∫ d<var>φ</var>/sin <var>φ</var> = ln
    tan(<var>φ</var>/2), pa je rješenje tan(<var>φ</var>(<var>t</var>)/2) =
    tan(<var>φ</var>₀/2) e<sup>−<var>t</var></sup>. Dakle, <var>q</var>(<var>t</var>) je tačka SLERP-a za
    <var>s</var>(<var>t</var>) = 1 − <var>φ</var>(<var>t</var>)/<var>φ</var>₀: tačno isti put kao SLERP, ali drugim
    tempom. Ovo <var>s</var>(<var>t</var>) je KLI-jevo <em>iskrivljenje vremena</em>: koliko je KLI odmakao duž
    SLERP-ovog luka u trenutku <var>t</var> (traka vremena postavlja <var>t</var>, a iskrivljenje je ono što tok od njega napravi).
    Njegova brzina je <var>s</var>′ = −<var>φ</var>′/<var>φ</var>₀ = sin <var>φ</var>/<var>φ</var>₀: počinje sa sin
    <var>φ</var>₀/<var>φ</var>₀ (0.827 za <var>φ</var>₀ = 60°) i eksponencijalno usporava kako stiže. (Brzina
    samog kvaterniona <var>q</var> po sferi na početku, |<var>q</var>′|, jednaka je sin <var>φ</var>₀.) Riječima:
    <var>q</var> se kreće duž dijela vektora <var>r</var> okomitog na <var>q</var>, čija je dužina sin <var>φ</var>. Daleko od
    <var>r</var> taj dio je velik; blizu <var>r</var> gotovo cijelo <var>r</var> leži duž <var>q</var> i malo toga preostaje da
    vuče, pa se preostali ugao u svakoj jedinici vremena smanjuje za gotovo isti udio i nikad ne dostiže 0. Zato
    metoda staje kad se <var>q</var> približi <var>r</var> na manje od zadate tolerancije (v. u nastavku).`,
  "kli.caption2":
    `Iskrivljenje vremena <var>s</var>(<var>t</var>) za <span class="kli">KLI</span> naspram <span class="slerp">SLERP</span>-a
    raspoređenog na isto vrijeme, <var>t</var>/<var>T</var>, gdje je <var>T</var> trenutak u kojem se metoda
    zaustavlja, čim je <var>q</var> unutar tolerancije oko <var>r</var> (izračunato u nastavku: 11.66 za primjer iz
    rada).`,
  "kli.p6":
    `<dfn id="def-algorithm-1">Algoritam 1</dfn> iz rada računa tok korak po korak: počni od <var>q</var> =
    <var>p</var>; napravi korak dužine <var>δ</var> u vremenu (ovdje metodom RK4, odjeljak 8); stani čim je
    ‖<var>r</var> − <var>q</var>‖ &lt; <var>ε</var> (dvostruke crte označavaju dužinu vektora u R⁴, ovdje
    četverodimenzionalnog vektora <var>r</var> − <var>q</var>). Njegova dva parametra su tolerancija <dfn
    id="def-epsilon"><var>ε</var></dfn>, koliko blizu je dovoljno blizu, i vremenski korak <dfn
    id="def-delta"><var>δ</var></dfn>. Rad koristi <var>ε</var> = 10⁻⁵ i <var>δ</var> = 0.01 i navodi <var>T</var> =
    11.66. Odakle to dolazi: ‖<var>r</var> − <var>q</var>‖ = 2 sin(<var>φ</var>/2), pa tok prvi put dođe unutar
    <var>ε</var> u trenutku`,
  "kli.p7":
    `<var>T</var>* = ln( tan(<var>φ</var>₀/2) / tan(arcsin(<var>ε</var>/2)) ) = 11.6568 za primjer iz rada,`,
  "kli.p8":
    `a petlja staje na prvom višekratniku od <var>δ</var> poslije toga, 11.66. Izvedi korake sam: <strong>Korak
    δ</strong> pomjera traku vremena za jedan korak, a tačka na grafiku je udaljenost u tom koraku.`,
  "kli.caption3":
    `‖<var>r</var> − <var>q<sub>n</sub></var>‖ u svakom koraku <var>t<sub>n</sub></var> = <var>nδ</var> na
    logaritamskoj skali, <var>ε</var> isprekidano, zaustavljanje <var>T</var> i <var>T</var>* tačkasto.`,
  "kli.legend1": "Algoritam 1",
  "kli.p9":
    `<output id="steps-out">Korak n = 0 pri t = 0.00: ‖r − q‖ = 1.00e+0. Uz ε = 10⁻⁵ i δ = 0.01 petlja staje nakon
    1166 koraka, pri T = 11.66; T* = 11.6568.</output>`,
  "kli.question1": "Predvidi, pa provjeri: u kojem je trenutku KLI na pola luka?",
  "kli.p10":
    `Koristi traku vremena: pola puta znači <var>φ</var> = 30°. Pogodi, pa <a class="set" href="?t=0.77#kli" data-t="0.77">idi
    na t = 0.77</a>.`,
  "kli.p11":
    `<strong>Odgovor.</strong> tan 15° = tan 30° e<sup>−<var>t</var></sup> daje <var>t</var> = ln(tan 30° / tan 15°)
    = 0.768, petnaestinu puta do <var>T</var>. Druga polovina traje preostalih 14 dijelova: brz početak, spor
    dolazak.`,
  "kli.question2": "Predvidi, pa provjeri: jedna cifra više, ε = 10⁻⁶. Koliko duže radi Algoritam 1?",
  "kli.p12":
    `Pogodi, pa <a class="set" href="?digits=6#kli" data-state='{"digits":6}'>postavi ε = 10⁻⁶</a>.`,
  "kli.p13":
    `<strong>Odgovor.</strong> Za mali <var>ε</var> je tan(arcsin(<var>ε</var>/2)) ≈ <var>ε</var>/2, pa svaka cifra
    dodaje ln 10 ≈ 2.303 vremenu <var>T</var>*: 13.9594, a petlja staje pri <var>T</var> = 13.96. Traka vremena i ose
    grafika sada idu do 15, pa se vide i zaustavljanje <var>T</var> i <var>T</var>*. Udaljenost opada kao
    e<sup>−<var>t</var></sup>, prava linija na logaritamskom grafiku.`,
  "kli.question3": "Napomena za čitaoce rada: štampana jednačina 4 i Tabela 1",
  "kli.p14":
    `Rad zapisuje jednačinu 3 po komponentama kao <var>q<sub>i</sub></var>′ = <var>r<sub>i</sub></var> −
    <var>q<sub>i</sub></var> − <var>q<sub>i</sub></var> cos <var>θ</var> (jednačina 4), gdje su <var>q<sub>i</sub></var>
    i <var>r<sub>i</sub></var> četiri dijela kvaterniona <var>q</var> i <var>r</var> (a ne oscilatori, kao u odjeljku
    6), a <var>θ</var> iz rada je <var>φ</var> u ovom vodiču. Suvišni
    −<var>q<sub>i</sub></var> je štamparska greška: s njim tok napušta sferu i smiruje se u tački dužine (√5 −
    1)/2 ≈ 0.618, nikad ne stižući do <var>r</var>. Ispravan oblik je <var>q<sub>i</sub></var>′ =
    <var>r<sub>i</sub></var> − <var>q<sub>i</sub></var> cos <var>θ</var>, uz cos <var>θ</var> =
    <var>q</var>·<var>r</var>, i Tabela 1 iz rada se s njim slaže. U Tabeli 1 red za <var>t</var> = 1.8 ponavlja
    red za 1.2; ispravne vrijednosti su 0.4364 + 0.4364 i + 0.4364 j + 0.6548 k. Oboje je provjereno na <a
    href="math.html#the-papers-example-section-3">stranici s matematikom</a> i testovima projekta.`,
  "integrators.title1": `<span class="number">8</span> Integratori i odstupanje`,
  "integrators.p1":
    `Računar prati tok u koracima dužine <var>h</var> u vremenu: isto što i <var>δ</var> Algoritma 1 u odjeljku
    7, ovdje nazvano <var>h</var> jer ova slika ima svoj klizač. <strong>Eulerov</strong> korak (isti Euler kao
    kod uglova i ose, njegova treća ideja), <var>q</var> + <var>h</var> <var>q</var>′, ide duž tangente, a korak
    po tangenti uvijek napušta sferu: |<var>q</var> + <var>h</var><var>v</var>|² = 1 +
    <var>h</var>²|<var>v</var>|² kad je <var>v</var> okomit na <var>q</var>. <dfn id="def-rk4">RK4</dfn>,
    klasična Runge–Kutta metoda četvrtog reda, u jednom koraku četiri puta računa izvod i uzima ponderisani
    prosjek dobijenih vrijednosti, (<var>k</var>₁ + 2<var>k</var>₂ + 2<var>k</var>₃ + <var>k</var>₄)/6, gdje su
    <var>k</var>₁ do <var>k</var>₄ te četiri vrijednosti izvoda (a ne kvaternionska jedinica k); njena greška
    opada kao <var>h</var>⁴, a tako i njeno odstupanje od sfere.`,
  "integrators.p5":
    `<strong>Geodezijski</strong> korak uzima prirast <var>Δ</var> metode RK4 i, umjesto da ga doda, ide po velikom
    krugu u njegovom smjeru: do <var>q</var> cos <var>α</var> + <var>u</var> sin <var>α</var>, gdje je <var>u</var>
    jedinični vektor duž dijela od <var>Δ</var> okomitog na <var>q</var>, a <var>α</var> ugao između <var>q</var> i
    <var>q</var> + <var>Δ</var>. Dva međusobno okomita jedinična vektora, pomnožena kosinusom i sinusom istog ugla,
    uvijek daju dužinu 1, pa je |<var>q</var>| = 1 po konstrukciji. Ovaj tok, zapisan kao <var>q</var>′ = <var>r</var> − (<var>q</var>·<var>r</var>)<var>q</var>
    (oblik koji ova stranica integrira; izvan sfere razlikuje se od −½(<var>q</var> <var>r̄</var> <var>q</var> −
    <var>r</var>) iz jednačine 3), vraća zalutali |<var>q</var>| prema 1: za svako
    <var>q</var>, d|<var>q</var>|²/d<var>t</var> = 2 <var>q</var>·<var>q</var>′ = 2(<var>q</var>·<var>r</var>)(1 −
    |<var>q</var>|²), što smanjuje |<var>q</var>| kad je veći od 1 i povećava ga kad je manji, sve dok je
    <var>q</var>·<var>r</var> &gt; 0 (na putu od <var>p</var> do <var>r</var> uvijek jeste). Zato ovdje odstupanje
    ne raste unedogled; kod drugih tokova može.`,
  "integrators.caption1":
    `| |<var>q</var>| − 1 | na primjeru iz rada za svaki integrator s korakom <var>h</var>, na logaritamskoj skali
    (ono što je ispod 10⁻¹⁷ crta se na 10⁻¹⁷); izabrani je podebljan. Pri kraju Eulerova linija može pasti ispod
    linije RK4: s velikim korakom Euler ide ispred tačnog toka i stiže ranije, a <var>q</var> koji se gotovo
    zaustavio više se ne udaljava od sfere. To je greška u vremenu, a ne veća tačnost.`,
  "integrators.legend1": "Integratori",
  "integrators.p2":
    `<output id="drift-out">Najveće odstupanje pri h = 0.5: Euler 9.0e-2, RK4 1.5e-3, geodezijski 2.2e-16.</output>`,
  "integrators.question1":
    `Predvidi, pa provjeri: prepolovi korak s 0.5 na 0.25. Koliko puta se smanje odstupanja Eulerove metode i RK4?`,
  "integrators.p3":
    `Savjet: odstupanje koje raste kao <var>h</var><sup><var>p</var></sup> postane 2<sup><var>p</var></sup> puta
    manje kad se <var>h</var> prepolovi, a odstupanje RK4 raste kao <var>h</var>⁴. Za Eulerovu metodu izračunaj
    odstupanje njenog prvog koraka iz gornje formule, √(1 + <var>h</var>²|<var>v</var>|²) − 1 uz |<var>v</var>| =
    sin 60° = 0.866, pri <var>h</var> = 0.5 i pri 0.25, i razmisli je li prvi korak i pri 0.25 još uvijek najgori.
    Pogodi, pa <a class="set" href="?h=0.25#integrators" data-state='{"step":0.25}'>postavi h = 0.25</a>.`,
  "integrators.p4":
    `<strong>Odgovor.</strong> Eulerovo oko 2.8 puta (s 0.090 na 0.032), RK4 oko 23 puta (s 1.5·10⁻³ na
    6.5·10⁻⁵). Eulerovo odstupanje nije nagomilavanje mnogo malih grešaka. Pri <var>h</var> = 0.5 najveće
    odstupanje je već u prvom koraku: iz <var>p</var> brzinom <var>v</var>, |<var>v</var>| = sin <var>φ</var>₀ =
    0.866, korak završava na dužini √(1 + <var>h</var>²|<var>v</var>|²), odstupanje √(1 + 0.1875) − 1 = 0.090;
    nakon toga tok vraća |<var>q</var>| nazad (0.057, zatim 0.017). Pri <var>h</var> = 0.25 prvi korak daje √(1
    + 0.047) − 1 = 0.023, a drugi gura još malo dalje, do 0.032, prije nego što privlačenje prevlada. Zašto je
    omjer između 2 i 4: svaki Eulerov korak gura |<var>q</var>|² prema van za <var>h</var>²|<var>v</var>|² i, po
    formuli za d|<var>q</var>|²/d<var>t</var> iznad, vraća višak |<var>q</var>|² − 1 za otprilike
    2<var>h</var>(<var>q</var>·<var>r</var>) puta taj višak. To dvoje je u ravnoteži pri višku od otprilike
    <var>h</var>|<var>v</var>|²/(2<var>q</var>·<var>r</var>), srazmjernom <var>h</var>: kad se <var>h</var>
    prepolovi, i on se prepolovi. Odstupanje prvog koraka, otprilike <var>h</var>²|<var>v</var>|²/2, umjesto
    toga postane 4 puta manje. Pri <var>h</var> = 0.5 najveće odstupanje je u prvom koraku, a pri 0.25 u nekom
    kasnijem, na putu ka ravnoteži: 2.8 je između 2 i 4. Odstupanje RK4 raste kao <var>h</var>⁴ (2⁴ = 16, nešto
    više pri ovako velikom koraku). Geodezijski korak ostaje na nivou greške zaokruživanja, oko 10⁻¹⁶.`,
  "many.title1": `<span class="number">9</span> Mnogo rotacija`,
  "many.p1":
    `Rad interpolira između dvije rotacije, a slučaj mnogo rotacija ostavlja kao otvoreno pitanje. Druge stranice
    ovog sajta se njime bave; svaka slika ispod je živa slika s njene stranice, učitana kad do nje stigneš.`,
  "many.heading1": "Ključni kadrovi: gladak okret kroz mnogo položaja",
  "many.p2":
    `Animator postavi zglobove lika u nekoliko trenutaka, ključnim kadrovima, a računar popuni ostalo. SLERP od
    ključa do ključa okreće ujednačeno na svakom dijelu, ali naglo skrene na svakom ključu, gdje se osa i
    brzina naglo promijene: skok ugaone brzine (brzine okretanja, vektora duž ose; <a href="#def-omega">definisana niže</a>), vidljiv skok
    na ekranu i udar momenta sile (uvrtanja koje motor mora dati) za motor ili kardan. KLI lanac (legenda slike ga
    zove Kuramoto–Lohe chain) na stranici
    <a href="keyframes.html">Mnogo rotacija</a> gusto uzorkuje cijelu krivu na S³ i fiksira uzorke u ključevima
    (fiksirani vođe, odjeljak 6); svaki drugi uzorak slijedi Kuramoto–Loheov tok, privlače ga susjedi, a odbijaju
    drugi susjedi, i smiri se na krivoj kroz ključeve čija se brzina okretanja mijenja glatko. (Između samo dva
    ključa to je SLERP-ov luk, kao i KLI.) Pomjeri <em>glatkoću</em> od 0 (SLERP po dijelovima) do 1. Slika crta kamo pokazuje
    nos (Hopfovo preslikavanje iz odjeljka 5) duž tri krive kroz iste ključeve: KLI lanac (narandžasto, puna linija),
    <dfn id="def-squad">Squad</dfn> (Shoemakeov splajn kvaterniona, uobičajena glatka kriva u softveru za animaciju,
    sastavljena od SLERP-ova između dodatnih kontrolnih tačaka; ljubičasto, isprekidano) i SLERP po dijelovima
    (tamno, tačkasto). Bijele tačke k0, k1, … su ključevi; k0 i k1 dijele jednu tačku, jer je prvi dio čisti okret oko nosa, koji
    Hopfovo preslikavanje ne može pokazati (odjeljak 5). Gledaj k2 i dio poslije njega: kako glatkoća raste, narandžasti lanac
    zaobljava ugao koji SLERP pravi u k2 i napušta tačkasti luk. Animacija na slici teče po svom satu, od k0
    pri <var>t</var> = 0 do k3 pri <var>t</var> = 3, a zatim kreće ispočetka; tri male ispunjene tačke označavaju položaj
    na svakoj od triju krivih u istom trenutku <var>t</var>. Ako je u postavkama tvog sistema uključeno smanjeno
    kretanje, slika miruje pri <var>t</var> = 2.5, između k2 i k3, gdje se krive razilaze.`,
  "many.p10":
    `Slika iznad prikazuje kamo je okrenut nos, a ne koliko se brzo tijelo okreće, a gledalac vidi upravo prelom u toj
    brzini. Tijelo koje se okreće u svakom trenutku se okreće oko neke ose nekom brzinom. Njegova <dfn id="def-omega">brzina
    okretanja</dfn>, ugaona brzina <var>ω</var>(<var>t</var>) (ne vlastite frekvencije <var>ω<sub>i</sub></var> iz odjeljka 6),
    jeste vektor duž te ose čija je dužina
    |<var>ω</var>| ta brzina, u radijanima po jedinici vremena (s kvaternionima, <var>q</var>′ = ½ <var>ω</var>
    <var>q</var>). SLERP od ključa do ključa okreće se oko jedne stalne ose jednolikom brzinom na svakom dijelu: dio
    koji se okrene za <var>θ</var> za vrijeme Δ<var>t</var> ima |<var>ω</var>| = <var>θ</var>/Δ<var>t</var>. U
    ključu preuzima sljedeći dio s drugom osom i brzinom, pa <var>ω</var> skoči: ugaono ubrzanje <var>ω̇</var>, brzina
    kojom se <var>ω</var> mijenja, tu je neograničeno, impuls: udar. U animaciji je to vidljiv skok u ključnom kadru; za kameru,
    podrhtavanje slike; za motor ili zglob robota, nagli skok momenta sile (oko nepomične ose, moment je moment
    inercije puta ugaono ubrzanje; u tri dimenzije, τ = <var>I</var><var>ω̇</var> + <var>ω</var> ×
    <var>I</var><var>ω</var>, gdje je <var>I</var> sada matrica inercije, a ne jedinična matrica iz odjeljka 1), koji opterećuje zupčanike i izaziva vibracije ruke robota. Klizač glatkoće postavlja KLI lanac od 0, što je
    sam SLERP po dijelovima, do 1, najglađeg; pri svakoj glatkoći većoj od 0, <var>ω</var>, pa čak i <var>ω̇</var>, mijenjaju se bez
    skoka.
    Ispod je brzina okretanja duž lanca kroz ista četiri ključa, od k0 pri <var>t</var> = 0 do k3 pri
    <var>t</var> = 3: to je vlastito vrijeme ključnih kadrova, a ne vrijeme na traci vremena.`,
  "many.caption1":
    `Lijevo (gore, na uskom ekranu): |<var>ω</var>(<var>t</var>)| za <span class="kli">KLI lanac</span> pri
    odabranoj glatkoći (debelo) i za SLERP po dijelovima (tamno, tačkasto), ključevi kao tačkaste linije, a skok
    vektora <var>ω</var> lanca upisan je uz svaki ključ gdje postoji. Desno (dolje): <var>ω</var> lanca po
    komponentama <span class="x">x</span>, <span class="y">y</span> i <span class="z">z</span>.`,
  "many.p11":
    `<output id="rates-out">Pri glatkoći 1 ω nema skoka ni u jednom ključu; njegova najveća brzina promjene |ω̇| je
    5.9 rad po jedinici vremena². SLERP po dijelovima skoči za 2.92 rad po jedinici vremena u k1.</output>`,
  "many.p12":
    `Svaka glatkoća veća od 0 već uklanja skokove: kriva lanca je tada klase C² (rotacija ima dva neprekidna
    izvoda, pa ni <var>ω</var> ni <var>ω̇</var> ne skaču), a <var>ω</var> se blizu ključa može samo brzo mijenjati,
    nikad odjednom. Mala glatkoća ima cijenu u velikom, iako konačnom, |<var>ω̇</var>|
    blizu ključeva; pri 1 promjena je raspoređena duž cijele krive. Ono što lanac tada čini najmanjim jeste
    koliko se kriva savija u R⁴: njegovi uzorci minimiziraju zbir koji predstavlja ∫|<var>q</var>″|²
    d<var>t</var>, gdje je <var>q</var>″ drugi izvod od <var>q</var>(<var>t</var>). Budući da je
    |<var>q</var>″|² = |<var>ω̇</var>|²/4 + |<var>ω</var>|⁴/16, taj zbir odmjerava ugaono ubrzanje naspram
    neravnomjerne brzine. Zato kriva pri 1 nije ona s najmanjim ∫|<var>ω̇</var>|² d<var>t</var> kroz ključeve,
    iako je na nasumičnim ključevima njen ∫|<var>ω̇</var>|² oko 0.8 Squadovog (0.78–0.84 u mjerenjima projekta; <a
    href="math.html#many-rotations-the-kuramotolohe-chain-the-papers-open-question">stranica o matematici</a>). Pomjeri klizač od 1 do 0.05 i prati kako
    navedeni |<var>ω̇</var>| raste, pa do 0, gdje više nije ograničen.`,
  "many.question2":
    `Predvidi, pa provjeri: pri glatkoći 0 oba dijela koja se sastaju u k2 okrenu se za 122.6° (2.14 rad) za
    jednu jedinicu vremena, pa je |ω| s obje strane 2.14. Skače li ω u k2, i za koliko?`,
  "many.p13":
    `Pogodi, pa <a class="set" href="?smooth=0#many-keyframes" data-state='{"smoothness":0}'>postavi glatkoću na
    0</a> i pogledaj k2 na oba grafika.`,
  "many.p14":
    `<strong>Odgovor.</strong> Da, za 2.53 rad po jedinici vremena. Brzina okretanja je vektor: dužina mu ostaje
    2.14, ali mu se osa u trenu zakrene za 72.6°, od (−0.410, 0.730, 0.547) do (0.730, 0.410, 0.547), a skok je dužina
    razlike, 2 × 2.14 × sin(72.6°/2) = 2.53. Zato grafik od |<var>ω</var>| u k2 nema stepenicu, dok komponente
    <var>x</var> i <var>y</var> vektora <var>ω</var> skaču (<var>z</var> ostaje 1.17). Za udar nije potrebna promjena brzine, dovoljna je
    promjena smjera: automobil koji bez kočenja uđe u oštru krivinu ipak baci putnike u stranu. Najveći skok je u
    k1, 2.92, gdje se mijenjaju i osa i brzina.`,
  "many.heading2": "Roj: sinhronizacija ili njena suprotnost",
  "many.p3":
    `Dronovi koji se usaglašavaju o smjeru leta, sateliti o položaju (orijentaciji letjelice u prostoru), jato koje
    skreće kao jedno: mnogo rotacija spregnutih neabelovim Kuramotovim (Loheovim) modelom iz odjeljka 6, gdje
    svaka privlači svaku, bez vođe. Na slici, sa stranice <a href="swarm.html">Roj</a>, svaka od 200 tačaka je jedna
    rotacija, nacrtana Hopfovim preslikavanjem tamo kamo usmjerava nos. Na početku su nasumično raspršene po S³.
    Sprezanje <var>K</var> određuje privlačenje. Za <var>K</var> &gt; 0 svaku privlače ostale: pri <var>K</var> = 1
    skupe se u jednu tačku do <var>t</var> = 8 po vlastitom satu slike, a ne po traci vremena (<dfn id="def-sync">sinhronizacija</dfn>, parametar reda
    <var>R</var> teži ka 1). Za <var>K</var> &lt; 0 privlačenje postaje odbijanje. Fiksiraj jednu od njih, vođu kao
    u odjeljku 6, i ostale se skupe na njoj; s jednim sljedbenikom to je KLI (tačno pri <var>K</var> = 2; drugi <var>K</var> prolazi isti put po
    satu koji je <var>K</var>/2 puta brži). Stranica Roj može fiksirati vođe, a
    KLI ima kao gotovu postavku.`,
  "many.question3":
    `Predvidi, pa provjeri: pri K = 1 tačke se skupe u jednu. Pri K = −1 svaka odbija ostale. Hoće li se razletjeti?`,
  "many.p15":
    `Pogodi, pa <button type="button" class="set-figure" data-figure="fig-swarm" data-attribute="coupling"
    data-value="-1">postavi K = −1</button> i prati tačke.`,
  "many.p16":
    `<strong>Odgovor.</strong> Ne: jedva se pomjere, najdalja za okret od oko 5°. Za jednake oscilatore, gdje
    svaki privlači svakog, tok povećava <var>K</var>|<var>m</var>|², gdje je <var>m</var> = (1/<var>N</var>)
    Σ<sub><var>j</var></sub> <var>q<sub>j</sub></var> njihova srednja vrijednost, a <var>R</var> = |<var>m</var>|.
    Odbijanje (<var>K</var> &lt; 0) smanjuje |<var>m</var>| na 0, što se zove <em>uravnoteženje</em>. Ali 200
    nasumično raspršenih rotacija već ima srednju vrijednost blizu 0, <var>R</var> = 0.034 na početku, pa ih mali
    pomak uravnoteži: <var>R</var> je 0.000 do <var>t</var> = 8 na vlastitom satu slike. Razmaknute su već bile.`,
  "many.heading3": "Usrednjavanje: jedna rotacija iz mnogo zašumljenih",
  "many.p4":
    `Kamera robota mnogo puta mjeri svoju orijentaciju, svaki put malo pogrešno, a nekoliko puta jako pogrešno:
    ta mjerenja su <dfn id="def-outlier">izuzeci</dfn> (autlajeri). Jednog sljedbenika privlače sva mjerenja
    odjednom, a privlačenje prema <var>r<sub>j</sub></var> ima težinu <var>q</var>·<var>r<sub>j</sub></var>. Ako
    <var>r<sub>j</sub></var> zamijeniš sa −<var>r<sub>j</sub></var>, i privlačenje i njegova težina mijenjaju
    predznak, pa se njihov proizvod ne mijenja: predznaci nisu bitni. Sljedbenik se smiri u <dfn
    id="def-chordal">tetivnoj sredini</dfn>, rotaciji <var>q</var> koja maksimizira
    Σ(<var>q</var>·<var>r<sub>j</sub></var>)².`,
  "many.p17":
    `<em>Tetivna</em> znači da se udaljenost ne mjeri po sferi, nego pravo kroz unutrašnjost, između matrica
    rotacije 3 × 3, <var>R<sub>q</sub></var> i <var>R<sub>j</sub></var>, koje pripadaju kvaternionima
    <var>q</var> i <var>r<sub>j</sub></var>; veličina matrice ovdje je kvadratni korijen zbira kvadrata njenih
    devet elemenata. Ako se dvije rotacije razlikuju za okret <var>θ</var>, onda je ‖<var>R<sub>q</sub></var> −
    <var>R<sub>j</sub></var>‖² = 3 + 3 − 2(1 + 2 cos <var>θ</var>) = 4 − 4 cos <var>θ</var>: svaka matrica ima
    tri jedinične kolone, a zbir devet proizvoda odgovarajućih elemenata jedne i druge matrice je 1 + 2 cos
    <var>θ</var>, trag okreta za <var>θ</var>. Kako je <var>θ</var> = 2<var>φ</var> (odjeljak 3) i cos
    2<var>φ</var> = 2(<var>q</var>·<var>r<sub>j</sub></var>)² − 1, to je jednako 8(1 −
    (<var>q</var>·<var>r<sub>j</sub></var>)²), isto za <var>r<sub>j</sub></var> i −<var>r<sub>j</sub></var>:
    kratkoj tetivi odgovara velik skalarni proizvod. (Kvadrat tetive između samih kvaterniona, |<var>q</var> −
    <var>r<sub>j</sub></var>|² = 2 − 2 <var>q</var>·<var>r<sub>j</sub></var>, daje umjesto toga
    <em>kvaternionsku sredinu</em>: prosjek mjerenja kao četvorki brojeva, podijeljen svojom dužinom. Ona zavisi
    od predznaka, pa se mjerenja prvo sva stave na istu stranu S³.)`,
  "many.p18":
    `<dfn id="def-karcher">Karcherova sredina</dfn> umjesto toga minimizira zbir kvadrata uglova okreta do
    mjerenja. Izuzeci odvlače obje sredine. <dfn id="def-median">Medijan</dfn>, rotaciju s najmanjim zbirom
    uglova (ne kvadrata) do mjerenja, izuzeci odvlače mnogo manje: izuzetak ga ne vuče jače od bliskog mjerenja.
    Stranica <a href="average.html">Usrednjavanje</a> računa sve četiri.`,
  "many.p19":
    `Pomjeri udio izuzetaka. Na slici svaka tačka pokazuje kamo mjerenje usmjerava nos: to je njegova Hopfova
    slika <var>h</var>(<var>r<sub>j</sub></var>); izuzeci imaju posebnu boju i dobiju prsten čim ih medijan
    izdvoji. ★ je istina, ● sljedbenik na putu od 1. Četiri sredine su bijeli krugovi s prstenom u svojoj boji:
    tetivna sredina narandžasto, kvaternionska sredina zeleno, Karcherova (geodezijska) sredina ljubičasto,
    medijan plavo. (Legenda slike imenuje svaku; stranica <a href="average.html">Usrednjavanje</a> ih prikazuje
    uz stupce istih boja.)`,
  "many.heading4": "Sinhronizacija rotacija na grafu",
  "many.p5":
    `Robot koji mapira zgradu (SLAM, simultana lokalizacija i mapiranje: istovremeno gradi mapu i pronalazi sebe u
    njoj) ili fotografije spojene u 3D model daju rotacije izmjerene između parova: kamera <var>j</var> u odnosu na
    kameru <var>i</var>, <var>R<sub>ij</sub></var> = <var>R<sub>i</sub></var>ᵀ<var>R<sub>j</sub></var>. Određivanje svih rotacija iz njih je sinhronizacija na grafu: svaka kamera je čvor, svako
    mjerenje grana. Rješenje je ono s najmanjom tetivnom cijenom <var>f</var> = Σ ‖<var>R<sub>i</sub></var>
    <var>R<sub>ij</sub></var> − <var>R<sub>j</sub></var>‖², zbirom po granama kvadrata koliko svako mjerenje
    promašuje (ista udaljenost pravo kroz unutrašnjost, ovdje između matrica).`,
  "many.p6":
    `Potraga za najmanjim <var>f</var> ide nizbrdo, a nizbrdo se može završiti u udubini koja nije najniža. Na
    stranici <a href="sync.html">Sinhronizacija rotacija</a> rješenje dolazi s <dfn
    id="def-certificate">certifikatom</dfn>, provjerom napravljenom naknadno: od rješenja i mjerenja sastavi se
    jedna velika simetrična matrica; ako njena najmanja svojstvena vrijednost nije negativna, može se dokazati da
    nijedan izbor rotacija nema manji <var>f</var>, pa je rješenje najbolje moguće, a ne samo najbolje u okolini.
    (Ako provjera ne uspije, ništa nije dokazano ni u jednom smjeru.) Pogrešne grane, izuzeci grafa, pronalaze se i
    izdvajaju.`,
  "many.p7":
    `Na slici je <var>f</var> ispisan na vrhu dok ga tok smanjuje: model iz rada pokrenut na grafu, u kojem
    svaka grana vuče oba svoja čvora, svaki ka mjestu na kojem bi, po njenom mjerenju, trebao biti. Svaka grana
    je obojena prema tome koliko se njeno mjerenje razlikuje od trenutnog rješenja: plavo ispod 2°, tirkizno
    2–5°, zeleno 5–15°, narandžasto 15–45°, crveno 45° ili više; pogrešna grana je isprekidana. Mjerenja između
    parova ne određuju čvorove jednoznačno: ako se svi čvorovi okrenu jednom zajedničkom rotacijom <var>G</var>,
    svaki proizvod (<var>G</var> <var>R<sub>i</sub></var>)ᵀ(<var>G</var> <var>R<sub>j</sub></var>) =
    <var>R<sub>i</sub></var>ᵀ<var>R<sub>j</sub></var> ostaje isti. Zato se rješenje poredi s istinom tek nakon
    jednog zajedničkog okreta koji ih najbolje poravna. Svaki čvor zatim nosi iglu: okret koji još ostaje između
    njegove prave rotacije i rotacije iz rješenja, primijenjen na osu <var>x</var> tijela, gledano odozgo. Igla
    pokazuje udesno kad se čvor slaže s istinom.`,
  "many.question1":
    `Predvidi, pa provjeri: na slici usrednjavanja, kad je pola mjerenja izuzetaka, koje sredine ostaju blizu istine?`,
  "many.p8":
    `Pogodi, pa <button type="button" class="set-figure" data-figure="fig-average" data-attribute="outliers"
    data-value="0.5">neka pola mjerenja budu izuzeci</button>.`,
  "many.p9":
    `<strong>Odgovor.</strong> Kvaternionsku sredinu (zeleno) i Karcherovu sredinu (ljubičasto) izuzeci odvuku
    najdalje, za oko 11° i 12°; tetivnu sredinu (narandžasto) manje, za oko 6°, jer kvadrat tetive do izuzetka nikad
    ne prelazi 8; medijan (plavo), koji svako mjerenje računa samo njegovom udaljenošću, ostaje unutar oko 2°, kako
    pokazuje tabela na stranici <a href="average.html">Usrednjavanje</a>.`,
  "glossary.title1": "Pojmovnik",
  "glossary.term1": "Algoritam 1",
  "glossary.definition1":
    `Petlja iz rada: pomjeraj tok za <var>δ</var> od <var>p</var> dok ne dođeš unutar <var>ε</var> od <var>r</var>.
    <a href="#def-algorithm-1">Odjeljak 7</a>`,
  "glossary.term28": "ugaona brzina (brzina okretanja)",
  "glossary.definition28":
    `<var>ω</var>, vektor duž ose oko koje se rotacija okreće, čija je dužina brzina u radijanima po jedinici
    vremena; <var>q</var>′ = ½ <var>ω</var> <var>q</var>. Skok u njoj je neograničeno ugaono ubrzanje,
    impuls: udar. <a href="#def-omega">Odjeljak 9</a>`,
  "glossary.term2": "certifikat",
  "glossary.definition2":
    `Provjera da je izračunato rješenje najbolje od svih, a ne samo lokalno. <a href="#def-certificate">Odjeljak 9</a>`,
  "glossary.term3": "tetivna sredina",
  "glossary.definition3":
    `Rotacija koja maksimizira Σ(<var>q</var>·<var>r<sub>j</sub></var>)² po mjerenjima. <a
    href="#def-chordal">Odjeljak 9</a>`,
  "glossary.term4": "dvostruko natkrivanje",
  "glossary.definition4":
    `<var>q</var> i −<var>q</var> su ista rotacija: S³ natkriva rotacije dvaput. <a
    href="#def-double-cover">Odjeljak 3</a>`,
  "glossary.term5": "δ (delta)",
  "glossary.definition5":
    `Vremenski korak Algoritma 1; u radu je 0.01 (odjeljak 8 korak naziva <var>h</var>). <a
    href="#def-delta">Odjeljak 7</a>`,
  "glossary.term6": "ε (epsilon)",
  "glossary.definition6":
    `Tolerancija Algoritma 1: stani čim je ‖<var>r</var> − <var>q</var>‖ &lt; <var>ε</var>; u radu je 10⁻⁵. <a
    href="#def-epsilon">Odjeljak 7</a>`,
  "glossary.term7": "vlakno",
  "glossary.definition7":
    `Kružnica na S³ koju Hopfovo preslikavanje šalje u jednu tačku sfere S²: rotacije koje se razlikuju za valjanje
    oko nosa. <a href="#def-fibre">Odjeljak 5</a>`,
  "glossary.term8": "geodezijska linija",
  "glossary.definition8":
    `Najkraći put po zakrivljenoj površi; na sferi, luk velikog kruga. <a href="#def-geodesic">Odjeljak 3</a>`,
  "glossary.term9": "Hopfovo preslikavanje",
  "glossary.definition9":
    `<var>h</var>: S³ → S², <var>h</var>(<var>q</var>) = <var>q</var> i <var>q̄</var>, kamo je usmjeren nos
    (jednačina 5 u radu). <a href="#def-hopf">Odjeljak 5</a>`,
  "glossary.term10": "Karcherova sredina",
  "glossary.definition10":
    `Rotacija koja minimizira zbir kvadrata uglova okreta do mjerenja (geodezijska sredina). <a
    href="#def-karcher">Odjeljak 9</a>`,
  "glossary.term11": "KLI",
  "glossary.definition11":
    `Kuramoto–Lohe interpolacija: tok iz rada <var>q</var>′ = <var>r</var> −
    (<var>q</var>·<var>r</var>)<var>q</var> od <var>p</var> do <var>r</var>. <a href="#def-kli">Odjeljak 7</a>`,
  "glossary.term12": "Kuramotov model",
  "glossary.definition12":
    `Oscilatori s vlastitim frekvencijama, od kojih svakog privlače faze ostalih. <a href="#def-kuramoto">Odjeljak
    6</a>`,
  "glossary.term13": "parametar reda",
  "glossary.definition13":
    `<var>R</var>, dužina prosječne tačke oscilatora (na S³, srednje vrijednosti kvaterniona
    <var>q<sub>j</sub></var>): 0 raštrkani, 1 usklađeni. <a href="#def-order">Odjeljak 6</a>`,
  "glossary.term14": "izuzetak (autlajer)",
  "glossary.definition14": `Mjerenje daleko od istine, a ne samo zašumljeno. <a href="#def-outlier">Odjeljak 9</a>`,
  "glossary.term15": "kvaternion",
  "glossary.definition15":
    `Broj <var>a</var> + <var>b</var> i + <var>c</var> j + <var>d</var> k uz i² = j² = k² = ijk = −1. <a
    href="#def-quaternion">Odjeljak 2</a>`,
  "glossary.term16": "RK4",
  "glossary.definition16":
    `Klasična Runge–Kutta metoda četvrtog reda: četiri izvoda po koraku, greška reda <var>h</var>⁴. <a
    href="#def-rk4">Odjeljak 8</a>`,
  "glossary.term17": "S³",
  "glossary.definition17":
    `3-sfera: tačke prostora R⁴ na udaljenosti 1 od ishodišta, jedinični kvaternioni. <a href="#def-s3">Odjeljak
    3</a>`,
  "glossary.term18": "SLERP",
  "glossary.definition18":
    `Sferna linearna interpolacija: luk velikog kruga od <var>p</var> do <var>r</var> konstantnom brzinom. <a
    href="#def-slerp">Odjeljak 4</a>`,
  "glossary.term19": "Squad",
  "glossary.definition19":
    `Shoemakeov splajn kvaterniona: glatka kriva kroz mnogo ključeva, sastavljena od SLERP-ova. <a
    href="#def-squad">Odjeljak 9</a>`,
  "glossary.term20": "sinhronizacija",
  "glossary.definition20":
    `Usaglašavanje mnogo rotacija: međusobno usklađene (roj) ili u skladu s mjerenjima između parova (graf). <a
    href="#def-sync">Odjeljak 9</a>`,
  "glossary.term21": "jedinični kvaternion",
  "glossary.definition21":
    `Kvaternion dužine 1; svaki je rotacija, a svaka rotacija su dva takva. <a
    href="#def-unit-quaternion">Odjeljak 2</a>`,
  "glossary.term22": "konjugovani kvaternion",
  "glossary.definition22":
    `Za <var>q</var> = <var>a</var> + <var>b</var> i + <var>c</var> j + <var>d</var> k: <var>q̄</var> = <var>a</var> −
    <var>b</var> i − <var>c</var> j − <var>d</var> k; za jedinični kvaternion, suprotni okret. <a href="#turn">Odjeljak 2</a>`,
  "glossary.term23": "skalarni proizvod",
  "glossary.definition23":
    `Za dva kvaterniona, <var>p</var>·<var>r</var>: njihova četiri dijela pomnožena u parovima i sabrana; za jedinične,
    kosinus ugla <var>φ</var> među njima. <a href="#cover">Odjeljak 3</a>`,
  "glossary.term24": "veliki krug",
  "glossary.definition24":
    `Presjek sfere i ravni kroz njen centar: najveće kružnice sfere i njeni najkraći putevi. <a
    href="#def-geodesic">Odjeljak 3</a>`,
  "glossary.term25": "ključni kadar",
  "glossary.definition25":
    `Orijentacija zadana u nekom trenutku (animatorova, tačka na putu robota) kroz koju glatki okret mora proći. <a
    href="#many">Odjeljak 9</a>`,
  "glossary.term26": "Loheov model",
  "glossary.definition26":
    `Kuramotov model proširen sa faza na kružnici na rotacije na S³ (neabelov Kuramotov model): svaki jedinični
    kvaternion vučen po sferi prema ostalima. <a href="#kuramoto">Odjeljak 6</a>`,
  "glossary.term27": "fiksirani vođa",
  "glossary.definition27":
    `Oscilator Loheovog modela koji miruje, a ostali (sljedbenici) teku prema njemu; sa jednim sljedbenikom, to je KLI. <a
    href="#def-leader">Odjeljak 6</a>`,
  "glossary.term29": "medijan",
  "glossary.definition29":
    `Rotacija s najmanjim zbirom uglova (ne kvadrata) do mjerenja, tako da je izuzetak ne vuče jače od bliskog
    mjerenja. <a href="#def-median">Odjeljak 9</a>`,
  "paper.title1": "Literatura",
  "paper.item1":
    `Zinaid Kapić i Aladin Crnkić, <span lang="en">“Interpolating Rotations with Non-abelian Kuramoto Model on the
    3-Sphere”</span> (Interpolacija rotacija neabelovim Kuramotovim modelom na 3-sferi), preprint, Tehnički
    fakultet, Univerzitet u Bihaću. Jednačine (3) i (5), Algoritam 1, Tabela 1 i <var>T</var> = 11.66 navedeni su
    iz njega; prateći video: <a
    href="https://www.youtube.com/watch?v=IkE_olufAuI">youtube.com/watch?v=IkE_olufAuI</a>.`,
  "paper.item2":
    `Y. Kuramoto, <span lang="en">“Self-entrainment of a population of coupled non-linear oscillators”, Lecture Notes
    in Physics</span> 39, Springer, 1975.`,
  "paper.item3":
    `M. A. Lohe, <span lang="en">“Non-Abelian Kuramoto models and synchronization”, Journal of Physics A</span> 42,
    395101, 2009.`,
  "paper.item4": `K. Shoemake, <span lang="en">“Animating rotation with quaternion curves”</span>, SIGGRAPH 1985.`,
  "save.intro":
    `Svaka slika vodiča onakva kakva je sada, kao slika (PNG, dvostruka rezolucija ekrana) ili za štampu (SVG,
    vektorski); put Algoritma 1 na primjeru iz rada kao podaci.`,
  "footer.p1":
    `Rust → WebAssembly; svaki broj na ovoj stranici izračunava se u tvom pregledniku kodom npm paketa
    <code>kli</code>. Tipke: Space pusti/pauziraj, ← → pomjeri traku vremena, Home ponovo; strelice okreću sferu iz
    odjeljka 5 kad je ona u fokusu. Dalje: isprobaj dvije rotacije iz rada na stranici <a href="index.html">KLI: dvije
    rotacije</a>.`,
  "care.label1": "Skretanje",
  "care.label2": "Propinjanje",
  "care.label3": "Nagib",
  "turn.label1": "Osa",
  "turn.label2": "Ugao θ",
  "slerp.label1": "s",
  "hopf.label1": "Valjanje ρ",
  "kuramoto.label1": "Sprezanje K",
  "kuramoto.label2": "Sprezanje K",
  "kli.label1": "Cifre od ε",
  "kli.label2": "Korak δ",
  "integrators.label1": "Integrator",
  "integrators.label2": "Korak h",
  "many.legend1": "Ključni kadrovi",
  "many.label1": "Glatkoća",
  "many.label2": "Sprezanje K",
  "many.label3": "Udio izuzetaka",
  "many.label4": "Udio pogrešnih grana",
  "clock.label1": "Vrijeme",
  "care.value1": "skretanje 30°",
  "care.value2": "propinjanje 40°",
  "care.value3": "nagib 0°",
  "turn.option1": "dijagonala, (1, 1, 1)/√3",
  "turn.value1": "90° oko z",
  "hopf.value1": "valjanje oko nosa 0°",
  "kuramoto.button1": "Pusti od t = 0",
  "kuramoto.button2": "Pusti od t = 0",
  "kli.button1": "Nazad δ",
  "kli.button2": "Korak δ",
  "kli.button3": "Pusti od t = 0",
  "integrators.option1": "geodezijski",
  "many.fallback1":
    `Živa slika sa stranice <a href="keyframes.html">Mnogo rotacija</a> pojavit će se ovdje kad stigneš do nje.`,
  "many.fallback2": `Živa slika sa stranice <a href="swarm.html">Roj</a> pojavit će se ovdje kad stigneš do nje.`,
  "many.fallback3": `Živa slika sa stranice <a href="average.html">Usrednjavanje</a> pojavit će se ovdje kad stigneš do nje.`,
  "many.fallback4":
    `Živa slika sa stranice <a href="sync.html">Sinhronizacija rotacija</a> pojavit će se ovdje kad stigneš do nje.`,
  "clock.button1": "Pusti",
  "clock.button2": "Ponovo",
  "clock.link1": "Veza na ovaj prikaz",
  "contents.aria1": "Sadržaj",
  "care.aria1": "Avion zaokrenut skretanjem, propinjanjem i nagibom, s osama skretanja, propinjanja i nagiba nacrtanim isprekidanim linijama.",
  "turn.aria1": "Avion zaokrenut oko izabrane ose za izabrani ugao, osa nacrtana kroz njega, njegova četiri broja ispod.",
  "cover.aria1": "Kružnica na S³ kroz 1 i osu, na kojoj su q i minus q suprotne tačke, i avion zaokrenut za q i za minus q, koji izgleda isto.",
  "cover.aria2": "Postavi ugao θ",
  "slerp.aria1": "Luk na S³ od p do r s tačkom SLERP-a i tačkom NLERP-a pri s, i oznakama na svakih 0.1 od s za obje: ravnomjernim za SLERP, neravnomjernim za NLERP.",
  "hopf.role1": "sfera koja se okreće",
  "hopf.aria1": "Sfera S² s tačkom nosa h(q) i tačkom krila na kružnici pravaca okomitih na nos. Tipke sa strelicama okreću sferu; okreće se i povlačenjem.",
  "hopf.aria2": "Avion iz odjeljka 2, zaokrenut oko nosa za izabrani ugao.",
  "kuramoto.aria1": "Dvadeset faza kao tačke na kružnici, parametar reda kao strelica iz središta, a pored njih parametar reda R u zavisnosti od vremena.",
  "kuramoto.aria2": "Osam sljedbenika na S³, nacrtanih Hopfovim slikama na sferi s tragovima, kako teku prema fiksiranom vođi r.",
  "kli.aria1": "Veliki krug kroz p i r s q u prikazanom trenutku, r rastavljen na dio duž q i tangentni dio, koji je q prim.",
  "kli.aria2": "Koliko je KLI odmakao duž luka u zavisnosti od vremena, brz rast koji se izravnava, pored prave linije SLERP-a koja stiže do kraja u T.",
  "kli.aria3": "Udaljenost od r u svakom koraku Algoritma 1 na logaritamskoj skali, opada pravolinijski dok ne padne ispod epsilon u T.",
  "integrators.aria1": "Odstupanje dužine q od 1 u zavisnosti od vremena na logaritamskoj skali za Eulerov, RK4 i geodezijski korak, izabrani podebljan.",
  "many.figure1": "Hopfove krive kroz četiri ključna kadra",
  "many.aria1":
    "Brzina okretanja u zavisnosti od vremena kroz četiri ključna kadra: njena veličina za KLI lanac i za SLERP " +
    "po dijelovima, koji u ključevima skače, i tri komponente lanca.",
  "many.valuetext1": "glatkoća 1",
  "many.figure2": "200 rotacija roja na Hopfovoj sferi",
  "many.figure3": "Mjerenja i njihove sredine na Hopfovoj sferi",
  "many.valuetext2": "20% izuzetaka",
  "many.figure4": "Graf rotacija, grane obojene prema tome koliko se svako mjerenje razlikuje od rješenja",
  "many.valuetext3": "10% pogrešnih",
  "clock.aria1": "Traka vremena vodiča",
};

/** Tekst koji page.js piše dok se slike mijenjaju. */
export const live = {
  /** The heading of the exercises' answers, printed at the end of the handout. */
  answers: "Odgovori na pitanja",
  /** Osa okreta u rečenici. */
  axes: { x: "x", y: "y", z: "z", diagonal: "dijagonale (1, 1, 1)" },
  /** Vrijednost svakog klizača riječima, pored njega i za čitač ekrana (`aria-valuetext`). */
  values: {
    yaw: (/** @type {string} */ v) => `skretanje ${v}°`,
    pitch: (/** @type {string} */ v) => `propinjanje ${v}°`,
    bank: (/** @type {string} */ v) => `nagib ${v}°`,
    angle: (/** @type {string} */ v, /** @type {string} */ axis) => `${v}° oko ${axis}`,
    roll: (/** @type {string} */ v) => `valjanje oko nosa ${v}°`,
  },
  /** Klizači slika s drugih stranica riječima (`aria-valuetext`). */
  figures: {
    smoothness: (/** @type {string} */ v) => `glatkoća ${v}`,
    outliers: (/** @type {string} */ v) => `${v}% izuzetaka`,
    wrong: (/** @type {string} */ v) => `${v}% pogrešnih`,
  },
  /** Brzina okretanja iz odjeljka 9: lanca, sa skokom ili bez njega (pri glatkoći 0). */
  rates: {
    jump: (/** @type {Record<string, string>} */ v) =>
      `Pri glatkoći 0 lanac je SLERP po dijelovima: u k${v.key} ω u trenu skoči za ${v.jump} rad po jedinici ` +
      `vremena, što je neograničeno ugaono ubrzanje.`,
    smooth: (/** @type {Record<string, string>} */ v) =>
      `Pri glatkoći ${v.s} ω nema skoka ni u jednom ključu; njegova najveća brzina promjene |ω̇| je ${v.acceleration} ` +
      `rad po jedinici vremena². SLERP po dijelovima skoči za ${v.slerpJump} rad po jedinici vremena u k${v.slerpKey}.`,
  },
  slerp: (/** @type {Record<string, string>} */ v) => `Pri s = ${v.s} SLERP je ${v.slerp}° duž luka, NLERP ${v.nlerp}°.`,
  hopf: (/** @type {Record<string, string>} */ v) => `Nos pokazuje prema ${v.nose}; krilo prema ${v.wing}.`,
  drift: (/** @type {Record<string, string>} */ v) =>
    `Najveće odstupanje pri h = ${v.h}: Euler ${v.euler}, RK4 ${v.rk4}, geodezijski ${v.geodesic}.`,
  phases: (/** @type {Record<string, string>} */ v) => `Pri t = ${v.t}, R = ${v.order}.`,
  lohe: (/** @type {Record<string, string>} */ v) =>
    `Pri t = ${v.t}, R = ${v.order}; najdalji sljedbenik je okret od ${v.spread}° od r.`,
  kli: (/** @type {Record<string, string>} */ v) => `Pri t = ${v.t}, φ = ${v.phi}°, s = ${v.s}: q = ${v.q}.`,
  steps: (/** @type {Record<string, string>} */ v) =>
    `Korak n = ${v.n} pri t = ${v.t}: ‖r − q‖ = ${v.distance}. Uz ε = ${v.epsilon} i δ = ${v.delta} petlja staje ` +
    `nakon ${v.steps} koraka, pri T = ${v.T}; T* = ${v.predicted}.`,
  /** Vrijednost klizača vremena za čitač ekrana. */
  time: (/** @type {string} */ t, /** @type {string} */ end) => `t = ${t} od ${end}`,
  /** Tekstualne alternative platna kad vrijeme stane. */
  labels: {
    phases: (/** @type {Record<string, string>} */ v) =>
      `Dvadeset Kuramotovih faza na kružnici pri t = ${v.t}: parametar reda R = ${v.order}.`,
    lohe: (/** @type {Record<string, string>} */ v) =>
      `Osam sljedbenika na S³ teče prema fiksiranom vođi pri t = ${v.t}: najdalji je ${v.spread}° od njega.`,
    kli: (/** @type {Record<string, string>} */ v) =>
      `KLI na velikom krugu od p do r pri t = ${v.t}: φ = ${v.phi}°, brzina je tangentni dio vektora r.`,
    clock: (/** @type {Record<string, string>} */ v) =>
      `Napredak KLI-ja duž luka u zavisnosti od vremena: s = ${v.s} pri t = ${v.t}, isprva brzo, zatim sporo; SLERP je prava linija.`,
    steps: (/** @type {Record<string, string>} */ v) =>
      `Udaljenost Algoritma 1 do r u svakom koraku na logaritamskoj skali, pravolinijski pad; ${v.steps} koraka, zaustavljanje pri T = ${v.T}.`,
  },
  /** Naslovni red sačuvanog videa. */
  video: "KLI: tok iz rada na velikom krugu i njegovo iskrivljenje vremena",
  /** Vrijednost iz adrese koju modul nije prihvatio, po ključu kontrole: `got` je vrijednost kako ju je adresa dala. */
  refused: {
    axis: (/** @type {string} */ got) => `osa mora biti x, y, z ili diagonal (dato je ${got})`,
    integrator: (/** @type {string} */ got) => `integrator mora biti euler, rk4 ili geodesic (dato je ${got})`,
    digits: (/** @type {string} */ got) => `cifre od ε moraju biti cijeli broj od 1 do 10 (dato je ${got})`,
    number: (/** @type {string} */ min, /** @type {string} */ max, /** @type {string} */ got) =>
      `mora biti broj od ${min} do ${max} (dato je ${got})`,
  },
};

/** Riječi koje modul crta na slikama (crates/kli-demo/src/learn/view.rs): `{ime}` tamo popunjava vrijednost. */
export const canvas = {
  yaw: "skretanje",
  pitch: "propinjanje",
  bank: "nagib",
  locked: "ose skretanja i nagiba se poklapaju: blokada kardana",
  apart: "ose skretanja i nagiba razmaknute {angle}°",
  axis: "osa",
  about: "{angle}° oko {axis}",
  diagonal: "dijagonale",
  turnedBy: "zaokrenut za q",
  turnedByMinus: "zaokrenut za −q",
  circle: "θ = {angle}°: q je {half}° duž kružnice",
  slerp: "s = {s}: SLERP {slerp}°, NLERP {nlerp}° (od 60°)",
  wing: "krilo",
  nose: "h(q): nos",
  rolled: "zaokrenut {angle}° oko nosa",
  order: "R(t), parametar reda",
  pinned: "h(r), fiksiran",
  widest: "t = {t}   najdalji: {angle}° od r",
  along: "koliko duž luka: s",
  steps: "‖r − qₙ‖ u svakom koraku",
  drift: "| |q| − 1 |, odstupanje od S³",
  largest: "{integrator}: najveće odstupanje {drift}",
  geodesic: "geodezijski",
  rate: "|ω(t)|, brzina okretanja",
  parts: "ω(t) po komponentama x, y, z",
  chain: "KLI lanac, glatkoća {smoothness}",
  pieces: "SLERP po dijelovima",
  jump: "skok {jump}",
};

/** Riječi zajedničkog izvršnog dijela na ovoj stranici, po njihovom engleskom; `{ime}` je vrijednost. */
export const runtime = {
  "Play": "Pusti",
  "Pause": "Pauza",
  "Text size": "Veličina teksta",
  "normal": "normalna",
  "large (1.5×)": "velika (1.5×)",
  "projector (2×)": "projektor (2×)",
  "hall (3×)": "sala (3×)",
  "Loading the WebAssembly module…": "Učitava se WebAssembly modul…",
  "The WebAssembly module could not be loaded: {error}": "WebAssembly modul se nije mogao učitati: {error}",
  "{key} must be from {min} to {max} on this page, as its slider (got {value})":
    "{key} mora biti od {min} do {max} na ovoj stranici, kao na klizaču (dato je {value})",
  "Pages": "Stranice",
  "KLI: two rotations": "KLI: dvije rotacije",
  "Many rotations": "Mnogo rotacija",
  "The swarm": "Roj",
  "Averaging": "Usrednjavanje",
  "Synchronising rotations": "Sinhronizacija rotacija",
  "Learn: a guided tour": "Uči: vodič",
  "The mathematics": "Matematika",
  "For teachers": "Za nastavnike",
  "With three.js": "Uz three.js",
  "Save": "Sačuvaj",
  "{noun} as {format}": "{noun} kao {format}",
  "Saved {what}.": "Sačuvano: {what}.",
  "Could not save: {error}": "Nije se moglo sačuvati: {error}",
  "Euler angles": "Eulerovi uglovi",
  "the Euler angles figure": "slika Eulerovih uglova",
  "Turn": "Okret",
  "the turn": "okret",
  "Double cover": "Dvostruko natkrivanje",
  "the double cover": "dvostruko natkrivanje",
  "SLERP": "SLERP",
  "the SLERP figure": "slika SLERP-a",
  "Hopf sphere": "Hopfova sfera",
  "the Hopf sphere": "Hopfova sfera",
  "Rolled object": "Tijelo okrenuto oko nosa",
  "the rolled object": "tijelo okrenuto oko nosa",
  "Phases": "Faze",
  "the Kuramoto phases": "Kuramotove faze",
  "Swarm on S³": "Roj na S³",
  "the swarm on S³": "roj na S³",
  "KLI": "KLI",
  "the KLI figure": "slika KLI-ja",
  "Time warp": "Iskrivljenje vremena",
  "the time warp": "iskrivljenje vremena",
  "Algorithm 1": "Algoritam 1",
  "Algorithm 1's steps": "koraci Algoritma 1",
  "Drift": "Odstupanje",
  "the drift": "odstupanje",
  "Turning rate": "Brzina okretanja",
  "the turning rate": "brzina okretanja",
  "Algorithm 1's path": "Put Algoritma 1",
  "Save a video": "Sačuvaj video",
  ["Each frame drawn for its own time (not filmed from the screen): smooth on any machine. MP4 and WebM play in " +
    "PowerPoint, Keynote and Google Slides; GIF goes anywhere ({rate} frames a second)."]:
    "Svaki kadar nacrtan za svoj trenutak (ne snima se ekran): glatko na svakom računaru. MP4 i WebM se reprodukuju " +
    "u programima PowerPoint, Keynote i Google Slides; GIF radi svuda ({rate} kadrova u sekundi).",
  "Format": "Format",
  "Size": "Veličina",
  "Frames a second": "Kadrova u sekundi",
  "From t =": "Od t =",
  "to t =": "do t =",
  "Length, seconds": "Trajanje, sekunde",
  "Figures in the clip:": "Slike u snimku:",
  "Save video": "Sačuvaj video",
  "Cancel": "Otkaži",
  "Video progress": "Napredak videa",
  "animated GIF": "animirani GIF",
  "{format} (this browser cannot encode it)": "{format} (ovaj preglednik ga ne može kodirati)",
  "Cannot save the video: {problem}.": "Video se ne može sačuvati: {problem}.",
  "Encoding the video…": "Kodira se video…",
  "Saved {name}: {frames} frames, {size} MB, encoded in {took} s.":
    "Sačuvano {name}: {frames} kadrova, {size} MB, kodirano za {took} s.",
  "The video was cancelled.": "Video je otkazan.",
  "Could not save the video: {error}": "Video se nije mogao sačuvati: {error}",
  "euler": "Eulerovi uglovi",
  "turn": "okret",
  "cover": "natkrivanje",
  "slerp": "SLERP",
  "hopf": "Hopfova sfera",
  "rolled": "valjanje",
  "phases": "faze",
  "lohe": "roj na S³",
  "kli": "KLI",
  "clock": "iskrivljenje vremena",
  "steps": "koraci",
  "drift": "odstupanje",
  "rates": "brzina okretanja",
};
