"""Realistic actuator and material records for judging ``hystcomp.diagnose``.

The mechanisms (:mod:`.mechanisms`) and excitations (:mod:`.excitations`) are written from
their physics, independently of hystcomp's model parts, so that a diagnosis tuned on the
library's own generator cannot pass by construction.

Two sets of cases: :data:`TUNING` (``cases.py``), on which the diagnosis may be tuned, and
:data:`HOLDOUT` (``cases_holdout.py``), kept apart: different parameter draws and mechanisms
and signals not in the tuning set. Each case is ``case(seed) -> Record``.
:data:`HOLDOUT2` (``cases_holdout2.py``) was written after the first tuning round and run once,
for that round's final measurement (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT3` (``cases_holdout3.py``) was written after that measurement and run once for
the third round's (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT4` (``cases_holdout4.py``) was written after that and run once for the fourth
round's final measurement (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT5` (``cases_holdout5.py``) was written after that and run once for the fifth
round's final measurement (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT6` (``cases_holdout6.py``) was written after that and run once for the sixth
round's final measurement (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT7` (``cases_holdout7.py``) was written after that and run once for the seventh
round's final measurement (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT8` (``cases_holdout8.py``) was written after that and run once for the eighth
round's final measurement (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT9` (``cases_holdout9.py``) was written after that and run once for the ninth
round's final measurement (docs/diagnose.md); it is part of :data:`ALL` since.
:data:`HOLDOUT10` (``cases_holdout10.py``) was written after that and run once for the tenth
round's final measurement (docs/diagnose.md, commit d112ea2, 17 of 30 runs right); it is part of
:data:`ALL` since.
:data:`HOLDOUT11` (``cases_holdout11.py``) was written after HOLDOUT10 was measured and run once
for the eleventh round's measurement (docs/diagnose.md, commit 587953b, 24 of 30 runs right); it is
part of :data:`ALL` since.
:data:`HOLDOUT12` (``cases_holdout12.py``) was written after HOLDOUT11 was measured and run once
for the twelfth round's measurement (docs/diagnose.md, commit 8ee476d, 26 of 30 runs right); it is
part of :data:`ALL` since.
:data:`HOLDOUT13` (``cases_holdout13.py``) was written after HOLDOUT12 was measured, by a session that
did not read how the diagnosis decides, and run once for the thirteenth round's measurement
(docs/diagnose.md, commit def11bb, 17 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT14` (``cases_holdout14.py``) was written after HOLDOUT13 was measured, by a session that did not read
how the diagnosis decides, and run once for the fifteenth round's measurement (docs/diagnose.md, commit 9f2684c,
26 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT15` (``cases_holdout15.py``) was written after HOLDOUT14 was measured, by a session that did not read
how the diagnosis decides, and run once for the seventeenth round's measurement (docs/diagnose.md, commit aba4dda,
20 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT16` (``cases_holdout16.py``) was written after HOLDOUT15 was measured, by a session that did not read
how the diagnosis decides, and run once for the eighteenth round's measurement (docs/diagnose.md, commit c126fec,
23 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT17` (``cases_holdout17.py``) was written after HOLDOUT16 was measured, by a session that did not read
how the diagnosis decides, and run once for the nineteenth round's measurement (docs/diagnose.md, commit 6dbd254,
24 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT18` (``cases_holdout18.py``) was written after HOLDOUT17 was measured, by a session that did not read
how the diagnosis decides, and run once for the twentieth round's measurement (docs/diagnose.md, commit 702bd44,
22 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT19` (``cases_holdout19.py``) was written after HOLDOUT18 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-first round's measurement (docs/diagnose.md, commit 193eae2,
24 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT20` (``cases_holdout20.py``) was written after HOLDOUT19 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-second round's measurement (docs/diagnose.md, commit 051b187,
25 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT21` (``cases_holdout21.py``) was written after HOLDOUT20 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-fourth round's measurement (docs/diagnose.md, commit 0686c5c,
23 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT22` (``cases_holdout22.py``) was written after HOLDOUT21 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-fifth round's measurement (docs/diagnose.md, commit c1403a2,
20 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT23` (``cases_holdout23.py``) was written after HOLDOUT22 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-sixth round's measurement (docs/diagnose.md, commit 7ffc669,
26 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT24` (``cases_holdout24.py``) was written after HOLDOUT23 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-sixth round's second measurement (docs/diagnose.md, commit
36a8c39, 24 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT25` (``cases_holdout25.py``) was written after HOLDOUT24 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-seventh round's measurement (docs/diagnose.md, commit
acecc42, 21 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT26` (``cases_holdout26.py``) was written after HOLDOUT25 was measured, by a session that did not read
how the diagnosis decides, and run once for the twenty-eighth round's measurement (docs/diagnose.md, commit
28c8ca8, 24 of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT27` (``cases_holdout27.py``) was written after HOLDOUT26 was measured, by a session that did not read how
the diagnosis decides, and run once for the twenty-ninth round's measurement (docs/diagnose.md, commit 7773baa, 22 of 30
runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT28` (``cases_holdout28.py``) was written after HOLDOUT27 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirtieth round's measurement (docs/diagnose.md, commit 7f0c36c, 27 of 30
runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT29` (``cases_holdout29.py``) was written after HOLDOUT28 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-first round's measurement (docs/diagnose.md, commit 9d75513, 28 of 30
runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT30` (``cases_holdout30.py``) was written after HOLDOUT29 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-second round's measurement (docs/diagnose.md, commit 0d0ebb8, 23 of
30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT31` (``cases_holdout31.py``) was written after HOLDOUT30 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-third round's measurement (docs/diagnose.md, commit ac02ee6, 21 of
30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT32` (``cases_holdout32.py``) was written after HOLDOUT31 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-fourth round's measurement (docs/diagnose.md, commit 15aba35, 15 of
30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT33` (``cases_holdout33.py``) was written after HOLDOUT32 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-fifth round's measurement (docs/diagnose.md, commit 4b75df5, 3 of
30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT34` (``cases_holdout34.py``) was written after HOLDOUT33 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-sixth round's measurement (docs/diagnose.md, commit 108a296, 7 of
30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT35` (``cases_holdout35.py``) was written after HOLDOUT34 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-seventh round's measurement (docs/diagnose.md, commit 52aa0a7, 9 of
30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT36` (``cases_holdout36.py``) was written after HOLDOUT35 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-eighth round's measurement (docs/diagnose.md, commit 7ce392d, 19
of 30 runs right); it is part of :data:`ALL` since.
:data:`HOLDOUT37` (``cases_holdout37.py``) was written after HOLDOUT36 was measured, by a session that did not read how
the diagnosis decides, and run once for the thirty-ninth round's measurement (docs/diagnose.md, commit e7034ae, 12 of
30 runs right); it is part of :data:`ALL` since.
Its core is a push-pull pair of liquid-nanofoam cells (water forced into a hydrophobic silica's ink-bottle pore network:
Laplace-Washburn entry through the necks, pore blocking, local emptying; Mason 1983 and 1988); a PI model of 12 plays
fitted by NNLS leaves 0.39 ... 0.61 sigma RMS on its clean record (at most 5.1 ... 11.1 sigma), measured in
tests/test_realistic_holdout37.py.
:data:`HOLDOUT38` (``cases_holdout38.py``) was written after HOLDOUT37 was measured, by a session that did not read how
the diagnosis decides, and run once for the fortieth round's measurement (docs/diagnose.md, commit 1512353, 20 of 30
runs right); it is part of :data:`ALL` since.
Its core is a voice coil pushing a long rod through a row of floating friction bushes, read at the coil (a series
stick-slip chain, the quasi-static Burridge-Knopoff chain, each bush's Coulomb grip behind an axial clearance); a PI
model of 12 plays fitted by NNLS leaves 0.60 ... 1.02 sigma RMS on its clean record (at most 1.9 ... 7.6 sigma),
measured in tests/test_realistic_holdout38.py.
:data:`HOLDOUT39` (``cases_holdout39.py``) was written after HOLDOUT38 was measured, by a session that did not read how
the diagnosis decides, and run once for the forty-first round's measurement (docs/diagnose.md, commit 37dfd93, 13 of
30 runs right); it is part of :data:`ALL` since.
Its core is a bulk (Bi,Pb)-2223 rod's critical state with Kim's field-dependent critical current and the rod's
demagnetising field, in a solenoid, read by a pickup coil and a fluxmeter; a PI model of 12 plays fitted by NNLS leaves
0.82 ... 1.35 sigma RMS on its clean record (at most 2.9 ... 5.6 sigma), measured in tests/test_realistic_holdout39.py.
:data:`HOLDOUT40` (``cases_holdout40.py``) was written after HOLDOUT39 was measured, by a session that did not read how
the diagnosis decides, and run once for the forty-second round's measurement (docs/diagnose.md, commit 7a59e35, 16 of
30 runs right); it is part of :data:`ALL` since. Its core is a soft PZT disc whose grains switch by 180 deg (each a relay of the local field with the thresholds (b +- E_c) /
cos(theta): Hwang, Lynch & McMeeking's switching criterion, log-normal coercive fields, random internal bias fields),
the switched polarisation's depolarising field in the mean-field approximation, AC-depoled before every record but the
initial-state case's, read by a charge amplifier; a PI model of 12 plays fitted by NNLS leaves 0.87 ... 1.30 sigma RMS
on its clean record (at most 7.9 ... 11.0 sigma), measured in tests/test_realistic_holdout40.py.
:data:`HOLDOUT41` (``cases_holdout41.py``) was written after HOLDOUT40 was measured, by a session that did not read how
the diagnosis decides, and run once for round 43's measurement (docs/diagnose.md, commit 309588c, 26 of 30 runs right);
it is part of :data:`ALL` since.
Its core is a sintered Mn-Zn ferrite toroid whose grains each hold one 180 deg domain wall pinned by its own random
landscape of defects and held by the grain's magnetostatic restoring force (Neel's walls in a random potential; the
quasi-static limit of the ABBM model: each wall slides to the first rest in the direction of its force), read by a
fluxmeter; a PI model of 12 plays fitted by NNLS leaves 0.84 ... 1.86 sigma RMS on its clean record (at most 3.8 ... 6.2
sigma), measured in tests/test_realistic_holdout41.py.
:data:`HOLDOUT42` (``cases_holdout42.py``) was written after HOLDOUT41 was measured, by a session that did not read how
the diagnosis decides, and run once for round 44's measurement (docs/diagnose.md, commit e785f31, 6 of 30 runs right);
it is part of :data:`ALL` since.
Its core is a NiTi shape-memory wire against a steel bias spring in a Peltier-controlled oil bath, read by a dial
indicator at the load: 1500 segments, each a relay of the effective temperature T - sigma / C between its own M_i and
A_i = M_i + w_i (Clausius-Clapeyron; Tanaka 1986, Liang & Rogers 1990, Ortin 1992), the shared stress falling as
martensite lengthens the wire against the spring (a negative feedback, segments stopping part-transformed), settled at
its loop's middle by a decaying thermal cycling before every record but the initial-state case's; a PI model of 12
plays fitted by NNLS leaves 3.5 ... 3.8 sigma RMS on its clean record (at most 15.2 ... 16.0 sigma), measured in
tests/test_realistic_holdout42.py: farther from a PI model than the sets before it.
:data:`HOLDOUT43` (``cases_holdout43.py``) was written after HOLDOUT42 was measured, by a session that did not read how
the diagnosis decides, and run once for round 45's measurement (docs/diagnose.md, commit 7bbed6c, 17 of 30 runs right);
it is part of :data:`ALL` since.
Its core is an electrowetting drop in oil whose contact line is pinned by its coating's defects (360 sectors, each a
stop of the Lippmann pull less the spherical cap's, tied to the mean radius by the line's elasticity; Young-Lippmann,
contact-angle hysteresis as Joanny & de Gennes 1984), the Lippmann term linear in the drive, read by a capacitance meter
as the footprint's area; a PI model of 12 plays fitted by NNLS leaves 0.71 ... 1.48 sigma RMS on its clean record (at
most 2.9 ... 4.9 sigma), measured in tests/test_realistic_holdout43.py.
:data:`HOLDOUT44` (``cases_holdout44.py``) was written after HOLDOUT43 was measured, by a session that did not read how
the diagnosis decides, and run once for round 46's measurement (docs/diagnose.md, commit 7ac7b7a, 20 of 30 runs right);
it is part of :data:`ALL` since.
Its core is an antagonistic pair of McKibben pneumatic muscles turning an arm's joint (Chou & Hannaford's and Tondu &
Lopez's force law p (a (1 - eps)^2 - b), two proportional regulators at the bias +- k u), the braid's contacts sliding
with dry friction proportional to their muscle's pressure (each a Jenkins element of the joint's travel), vented and
charged together before every record but the initial-state case's, read by an optical encoder; a PI model of 12 plays
fitted by NNLS leaves 0.92 ... 1.04 sigma RMS on its clean record (at most 3.0 ... 4.2 sigma), measured in
tests/test_realistic_holdout44.py.
:data:`HOLDOUT45` (``cases_holdout45.py``) was written after HOLDOUT44 was measured, by a session that did not read how
the diagnosis decides, and run once for round 47's measurement (docs/diagnose.md, commit 7384445, 8 of 30 runs right);
it is part of :data:`ALL` since.
Its core is a prestressed Terfenol-D rod in a magnetostrictive actuator (a bias sleeve's field on the bipolar records),
its domain walls pinned like dry friction (Bergqvist's model: every region a play of the field, magnetised as the
anhysteretic tanh of its play's output), the travel the 90 deg rotation's quadratic law Y (M / Ms)^2, assembled the
maker's way (the sleeve slid on, then the prestress, which carries the magnetisation toward the anhysteretic) before
every record but the initial-state cases', read by an eddy-current probe; a PI model of 12 plays fitted by NNLS leaves
1.2 ... 2.1 sigma RMS on its clean record (at most 11.4 ... 13.4 sigma), measured in tests/test_realistic_holdout45.py.
:data:`HOLDOUT46` (``cases_holdout46.py``) was written after HOLDOUT45 was measured, by a session that did not read how
the diagnosis decides, and run once for round 48's measurement (docs/diagnose.md, commit e9bf6a2, 22 of 30 runs right);
it is part of :data:`ALL` since.
Its core is a polypyrrole (PPy(DBS)) film on a gold-coated polyimide strip, a bilayer bender under a potentiostat, read
by a laser triangulation sensor: the film's domains each a Frumkin lattice gas of redox sites with attractive
interactions (g > 2: bistable, switching at its spinodals, E_i +- Delta(g); Laviron 1974, Dreyer et al. 2010), 600
classes on a golden-ratio lattice over normal formal potentials and log-normal interactions, a double layer beside
them, the curvature Stoney's limit of Timoshenko's bimetal formula, starting from the film as grown at the middle
potential (every domain in its stable state: the Preisach demagnetised state); a PI model of 12 plays fitted by NNLS
leaves 1.11 ... 1.79 sigma RMS on its clean record (at most 4.4 ... 5.7 sigma), measured in
tests/test_realistic_holdout46.py.
:data:`HOLDOUT47` (``cases_holdout47.py``) was written after HOLDOUT46 was measured, by a session that did not read how
the diagnosis decides, and run once for round 49's measurement (docs/diagnose.md, commit 4fe1988, 19 of 30 runs
right); it is part of :data:`ALL` since.
Its core is a polarised pair of magnetorheological-fluid clutches (a magnet's bias flux across both clutches' gaps, the
control coil's flux adding in one and subtracting in the other; Carlson's yield stress of the fluid, tanh of the gap's
field, the fluid's Frohlich-Kennelly magnetisation), the control flux through a low-carbon steel armature whose 1000
Barkhausen regions switch as a Preisach model sheared by the gaps (regions held part-switched at their thresholds),
demagnetised before every record but the initial-state case's, read by a reaction torque sensor; a PI model of 12 plays
fitted by NNLS leaves 1.12 ... 1.26 sigma RMS on its clean record (at most 6.0 ... 6.7 sigma), measured in
tests/test_realistic_holdout47.py.
:data:`HOLDOUT48` (``cases_holdout48.py``) was written after HOLDOUT47 was measured, by a session that did not read how
the diagnosis decides, and run once for round 50's measurement (docs/diagnose.md, commit 92e115f, 24 of 30 runs
right); it is part of :data:`ALL` since.
Its core is a magnetic shape-memory actuator: a Ni-Mn-Ga (10M) element between centring springs, its two coils' fields
driving its twin boundaries by the variants' magnetic energy difference (O'Handley 1998, Likhachev & Ullakko 2000),
1000 regions each swept by its boundary past its twinning stress and internal stress (a Preisach ensemble sheared by
the springs), centred by the controller's routine before every record but the initial-state case's, read by a laser
Doppler vibrometer; a PI model of 12 plays fitted by NNLS leaves 1.02 ... 1.48 sigma RMS on its clean record (at most
7.4 ... 10.4 sigma), measured in tests/test_realistic_holdout48.py.
:data:`HOLDOUT49` (``cases_holdout49.py``) was written after HOLDOUT48 was measured, by a session that did not read how
the diagnosis decides, and run once for round 51's measurement (docs/diagnose.md, commit 26142c2, 22 of 30 runs
right); it is part of :data:`ALL` since.
Its core is a magnetostrictive actuator's Galfenol (Fe-Ga) rod, <100>-textured and held in compression by a Belleville
spring stack: its domains turning out of the plane against the cubic anisotropy and the stress (a Stoner-Wohlfarth-type
energy with cubic anisotropy, the in-plane well's c the middle root of a cubic in closed form; Atulasimha & Flatau,
Armstrong), the walls between in-plane and axial domains pinned (4000 regions switching where the energy an axial
domain saves passes their pinning energy about their internal bias, 32 classes of local stress), the bias magnets'
rings in the return path feeding the rod's magnetisation back to its field (the ensemble sheared), demagnetised by the
controller's routine before every record but the initial-state cases', read by a capacitive gauge; a PI model of 12
plays fitted by NNLS leaves 1.28 ... 1.59 sigma RMS on its clean record (at most 4.7 ... 6.5 sigma), measured in
tests/test_realistic_holdout49.py.
:data:`HOLDOUT50` (``cases_holdout50.py``) was written after HOLDOUT49 was measured, by a session that did not read how
the diagnosis decides, and run once for round 52's measurement (docs/diagnose.md, commit 1d50c7f, 16 of 30 runs
right); it is part of :data:`ALL` since.
Its core is a robot wrist joint's harmonic drive (strain-wave gear) on a locked-output torsion bench, its motor in
current (torque) mode, its twist read by the motor's encoder: 42 tooth pairs, each pressed into its tooth space by the
wave generator's ellipse and held there by a wedge with friction (a seated tooth's detent; it rides out at P tan(beta +
phi) and slides back at P tan(beta - phi): the wedge's and the ring spring's law), the teeth bending in series and
sharing the rim's travel, the cup and fixture in series, and the wave generator's Coulomb friction, a play on the
motor's torque, before it all; at rest from the bench's zeroing before every record but the initial-state case's; a PI
model of 12 plays fitted by NNLS leaves 1.51 ... 2.10 sigma RMS on its clean record (at most 7.6 ... 10.2 sigma),
measured in tests/test_realistic_holdout50.py.
:data:`HOLDOUT51` (``cases_holdout51.py``) was written after HOLDOUT50 was measured, by a session that did not read how
the diagnosis decides, and run once for round 53's measurement (docs/diagnose.md, commit 1388680, 14 of 30 runs
right); it is part of :data:`ALL` since.
Its core is a multilayer stack of the relaxor 0.9 PMN - 0.1 PT, biased by its amplifier, driving a lever stage read by a
capacitive gauge: 4096 polar clusters with Smolenskii's spread of Curie temperatures, log-normal sizes and random
fields, each a Landau-Devonshire body in its well (the blocked ones switching where the thermally activated barrier
falls to 25 k T, the ergodic ones in their deeper well), the strain electrostrictive, Q P^2, the bias where the
curvatures of P and of its square cancel; at rest in the state the controller's start-up dither leaves at the bias
before every record but the initial-state case's; a PI model of 12 plays fitted by NNLS leaves 1.21 ... 1.64 sigma RMS
on its clean record (at most 5.3 ... 7.5 sigma), measured in tests/test_realistic_holdout51.py.
:data:`HOLDOUT52` (``cases_holdout52.py``) was written after HOLDOUT51 was measured, by a session that did not read how
the diagnosis decides, and run once for round 54's measurement (docs/diagnose.md, commit e91c307, 3 of 30 runs right);
it is part of :data:`ALL` since. Its core is a thin-film phase-change actuator: a film of silicone holding mesoporous silica whose
pores hold a broad-cut paraffin, on a heater chip under a temperature loop, read by a capacitive gauge: 6000 classes of
pores, each melting when a liquid sleeve can grow along its wall and freezing when the crystal can enter through its
mouth (Gibbs-Thomson at the two interfaces' curvatures, 1 / (r - t) and 2 / (q r - t): thermoporometry's
melting-freezing hysteresis; Brun et al. 1977, Petrov & Furo 2006), the pores' bulk melting points spread by the blend,
the film's thickness taking the matrix's and the wax's expansion and the wax's 10 % on melting; at rest in the state the
controller's decaying thermal conditioning leaves before every record but the initial-state case's; a PI model of 12
plays fitted by NNLS leaves 1.43 ... 1.55 sigma RMS on its clean record (at most 7.8 ... 10.2 sigma), measured in
tests/test_realistic_holdout52.py.
:data:`HOLDOUT53` (``cases_holdout53.py``) was written after HOLDOUT52 was measured, by a session that did not read how
the diagnosis decides, and run once for round 55's measurement (docs/diagnose.md, commit 464057e, 17 of 30 runs
right); it is part of :data:`ALL` since. Its core is a
metal-hydride actuator: an AB5 hydride powder (a blend of LaNi(5-y)Al(y)) behind a steel diaphragm, its hydrogen
pressure set by an electrochemical hydrogen pump at Nernst's equilibrium with the drive, 6000 classes of particles each
a relay of the pressure between its absorption and desorption plateaus (Everett's independent domains; the plateaus'
hysteresis the work of accommodating the hydride's swelling, Flanagan), the alpha phase's hydrogen by Sieverts' law and
the hydride's on its sloping branch, the lattice's swelling and the gas's pressure bowing the diaphragm, read by a
capacitive gauge; at rest in the state the controller's decaying pressure cycling leaves before every record but the
initial-state case's; a PI model of 12 plays fitted by NNLS leaves 1.49 ... 1.70 sigma RMS on its clean record (at most
6.9 ... 9.2 sigma), measured in tests/test_realistic_holdout53.py.
:data:`HOLDOUT54` (``cases_holdout54.py``) was written after HOLDOUT53 was measured, by a session that did not read how
the diagnosis decides, and run once for round 56's measurement (docs/diagnose.md, commit abb8290, 15 of 30 runs
right); it is part of :data:`ALL` since. Its core is a
spin-crossover composite strip: crystallites of an iron(II) triazole molecular alloy in a polyurethane matrix, its
temperature set from the drive, read by an LVDT: 3000 classes, each a cooperative Slichter-Drickamer body on the low- or
the high-spin branch of its free energy's minimum, switching at its spinodals (each branch bending with the
temperature), their T_half normal and their interaction log-normal, the strip's length taking the high-spin lattice's
volume and expansion; at rest in the state the controller's decaying thermal conditioning leaves before every record but
the initial-state case's; a PI model of 12 plays fitted by NNLS leaves 1.17 ... 1.41 sigma RMS on its clean record (at
most 6.7 ... 6.8 sigma), measured in tests/test_realistic_holdout54.py.
:data:`HOLDOUT55` (``cases_holdout55.py``) was written after HOLDOUT54 was measured, by a session that did not read how
the diagnosis decides, and run once for round 57's measurement (docs/diagnose.md, commit 58bc36b, 16 of 30 runs
right); it is part of :data:`ALL` since. Its core is a ferroelectric-polymer unimorph: a silicon cantilever
carrying a poled film of the
copolymer P(VDF-TrFE), its field set by the drive, its tip read by a fibre-optic displacement sensor: 4000 classes of
soft crystallites (single domains, each a relay of the field between E_c - E_b and -E_c - E_b, their coercive fields
log-normal and their internal fields normal) that the drive switches and 500 of hard ones that hold the remanent
polarisation, the film's in-plane strain electrostrictive (Q P^2) and the beam bent by Stoney's law; at rest in the
state the controller's decaying conditioning of the field leaves before every record but the initial-state case's; a PI
model of 12 plays fitted by NNLS leaves 1.77 ... 1.99 sigma RMS on its clean record (at most 7.6 ... 8.3 sigma),
measured in tests/test_realistic_holdout55.py.
:data:`HOLDOUT56` (``cases_holdout56.py``) was written after HOLDOUT55 was measured, by a session that did not read how
the diagnosis decides, and run once for round 58's measurement (docs/diagnose.md, commit ac5079b, 19 of 30 runs right);
it is part of :data:`ALL` since. Its core is a vanadium-dioxide thin-film bimorph: a cantilever of a VO2 film
co-sputtered with tungsten on a polyimide strip, on a heater chip under a temperature loop, read by a confocal chromatic
sensor: 6000 classes of grains, each switching whole between the insulating monoclinic and the metallic rutile phase at
its own temperatures (the metal-insulator transition, first order, its loop widening as the grain shrinks; Morin 1959,
Lopez et al. 2002), their transition temperatures spread by the tungsten, the beam bent by the grains' transformation
strain and the two layers' expansions (Timoshenko's bimetal, an arc); at rest in the state the controller's decaying
thermal conditioning leaves before every record but the initial-state case's; a PI model of 12 plays fitted by NNLS
leaves 1.48 ... 1.62 sigma RMS on its clean record (at most 9.0 ... 11.3 sigma), measured in
tests/test_realistic_holdout56.py.
:data:`HOLDOUT57` (``cases_holdout57.py``) was written after HOLDOUT56 was measured, by a session that did not read how
the diagnosis decides, and run once for round 59's measurement (docs/diagnose.md, commit f34eb11, 15 of 30 runs right);
it is part of :data:`ALL` since. Its core is a humidity-tuned optical filter: a Bragg mirror of mesoporous silica (cage-like
pores joined by narrower windows: ink bottles, impregnated with lithium chloride) and dense titania, in a cell fed by a
dew-point generator, its reflection peak read by a spectrometer: 6000 classes of cages, each filling with capillary
solution when the meniscus inside it becomes unstable and emptying only when the meniscus in its window can recede
(Kelvin with Cohan's menisci and Raoult's law for its salt; Cohan 1938, Ravikovitch & Neimark 2002), the empty cages
holding a BET film, the layer's index by the Lorentz-Lorenz rule; at rest in the state the generator's decaying
conditioning leaves before every record but the initial-state case's; a PI model of 12 plays fitted by NNLS leaves
1.49 ... 1.61 sigma RMS on its clean record (at most 10.8 ... 14.1 sigma), measured in
tests/test_realistic_holdout57.py.
:data:`HOLDOUT58` (``cases_holdout58.py``) was written after HOLDOUT57 was measured, by a session that did not read how
the diagnosis decides, and run once for round 60's measurement (docs/diagnose.md, commit a1f24a4, 19 of 30 runs right);
it is part of :data:`ALL` since. Its core is a multistable stage: a voice-coil motor on a flexure guide pressing,
each through its own soft spring, the middles of 400 pre-buckled silicon beams on a MEMS chip, read by a capacitive
gauge: each beam bistable (its first mode's cubic,
Vangbo's buckled beam) and snapping at its branches' folds under the soft spring (Cardano's roots between them), their
amplitudes, thicknesses and imperfections spread, all sharing the shuttle's travel (avalanches, return-point memory
kept); at rest in the state the controller's decaying dither leaves before every record but the initial-state case's;
how close a PI model of 12 plays comes to its clean record is measured in tests/test_realistic_holdout58.py.
:data:`HOLDOUT59` (``cases_holdout59.py``) was written after HOLDOUT58 was measured, by a session that did not read how
the diagnosis decides, and run once for round 61's measurement (docs/diagnose.md, commit 7e9d9ce, 20 of 30 runs right);
it is part of :data:`ALL` since. Its core is a thermoresponsive hydrogel film actuator: a film of PNIPAM microgels in a loose
polyacrylamide matrix on a heater chip under a temperature loop, read by an interferometer: 8000 classes of microgels,
each collapsing in its volume phase transition when heated past its T_c and reswelling only some degrees below it (the
collapsed globule's hydrogen bonds), their T_c spread over a blend of copolymer batches, a swollen one deswelling a
little ahead of its transition; at rest in the state the controller's decaying conditioning leaves before every record
but the initial-state case's; how close a PI model of 12 plays comes to its clean record is measured in
tests/test_realistic_holdout59.py.
"""

from .record import FAMILIES, Record, family  # noqa: F401
from .cases import TUNING  # noqa: F401
from .cases_holdout import HOLDOUT  # noqa: F401
from .cases_holdout2 import HOLDOUT2  # noqa: F401
from .cases_holdout3 import HOLDOUT3  # noqa: F401
from .cases_holdout4 import HOLDOUT4  # noqa: F401
from .cases_holdout5 import HOLDOUT5  # noqa: F401
from .cases_holdout6 import HOLDOUT6  # noqa: F401
from .cases_holdout7 import HOLDOUT7  # noqa: F401
from .cases_holdout8 import HOLDOUT8  # noqa: F401
from .cases_holdout9 import HOLDOUT9  # noqa: F401
from .cases_holdout10 import HOLDOUT10  # noqa: F401
from .cases_holdout11 import HOLDOUT11  # noqa: F401
from .cases_holdout12 import HOLDOUT12  # noqa: F401
from .cases_holdout13 import HOLDOUT13  # noqa: F401
from .cases_holdout14 import HOLDOUT14  # noqa: F401
from .cases_holdout15 import HOLDOUT15  # noqa: F401
from .cases_holdout16 import HOLDOUT16  # noqa: F401
from .cases_holdout17 import HOLDOUT17  # noqa: F401
from .cases_holdout18 import HOLDOUT18  # noqa: F401
from .cases_holdout19 import HOLDOUT19  # noqa: F401
from .cases_holdout20 import HOLDOUT20  # noqa: F401
from .cases_holdout21 import HOLDOUT21  # noqa: F401
from .cases_holdout22 import HOLDOUT22  # noqa: F401
from .cases_holdout23 import HOLDOUT23  # noqa: F401
from .cases_holdout24 import HOLDOUT24  # noqa: F401
from .cases_holdout25 import HOLDOUT25  # noqa: F401
from .cases_holdout26 import HOLDOUT26  # noqa: F401
from .cases_holdout27 import HOLDOUT27  # noqa: F401
from .cases_holdout28 import HOLDOUT28  # noqa: F401
from .cases_holdout29 import HOLDOUT29  # noqa: F401
from .cases_holdout30 import HOLDOUT30  # noqa: F401
from .cases_holdout31 import HOLDOUT31  # noqa: F401
from .cases_holdout32 import HOLDOUT32  # noqa: F401
from .cases_holdout33 import HOLDOUT33  # noqa: F401
from .cases_holdout34 import HOLDOUT34  # noqa: F401
from .cases_holdout35 import HOLDOUT35  # noqa: F401
from .cases_holdout36 import HOLDOUT36  # noqa: F401
from .cases_holdout37 import HOLDOUT37  # noqa: F401
from .cases_holdout38 import HOLDOUT38  # noqa: F401
from .cases_holdout39 import HOLDOUT39  # noqa: F401
from .cases_holdout40 import HOLDOUT40  # noqa: F401
from .cases_holdout41 import HOLDOUT41  # noqa: F401
from .cases_holdout42 import HOLDOUT42  # noqa: F401
from .cases_holdout43 import HOLDOUT43  # noqa: F401
from .cases_holdout44 import HOLDOUT44  # noqa: F401
from .cases_holdout45 import HOLDOUT45  # noqa: F401
from .cases_holdout46 import HOLDOUT46  # noqa: F401
from .cases_holdout47 import HOLDOUT47  # noqa: F401
from .cases_holdout48 import HOLDOUT48  # noqa: F401
from .cases_holdout49 import HOLDOUT49  # noqa: F401
from .cases_holdout50 import HOLDOUT50  # noqa: F401
from .cases_holdout51 import HOLDOUT51  # noqa: F401
from .cases_holdout52 import HOLDOUT52  # noqa: F401
from .cases_holdout53 import HOLDOUT53  # noqa: F401
from .cases_holdout54 import HOLDOUT54  # noqa: F401
from .cases_holdout55 import HOLDOUT55  # noqa: F401
from .cases_holdout56 import HOLDOUT56  # noqa: F401
from .cases_holdout57 import HOLDOUT57  # noqa: F401
from .cases_holdout58 import HOLDOUT58  # noqa: F401
from .cases_holdout59 import HOLDOUT59  # noqa: F401

ALL = {**TUNING, **HOLDOUT, **HOLDOUT2, **HOLDOUT3, **HOLDOUT4, **HOLDOUT5, **HOLDOUT6, **HOLDOUT7, **HOLDOUT8,
       **HOLDOUT9, **HOLDOUT10, **HOLDOUT11, **HOLDOUT12, **HOLDOUT13, **HOLDOUT14, **HOLDOUT15, **HOLDOUT16,
       **HOLDOUT17, **HOLDOUT18, **HOLDOUT19, **HOLDOUT20, **HOLDOUT21, **HOLDOUT22, **HOLDOUT23, **HOLDOUT24,
       **HOLDOUT25, **HOLDOUT26, **HOLDOUT27, **HOLDOUT28, **HOLDOUT29, **HOLDOUT30, **HOLDOUT31, **HOLDOUT32,
       **HOLDOUT33, **HOLDOUT34, **HOLDOUT35, **HOLDOUT36, **HOLDOUT37, **HOLDOUT38, **HOLDOUT39, **HOLDOUT40,
       **HOLDOUT41, **HOLDOUT42, **HOLDOUT43, **HOLDOUT44, **HOLDOUT45, **HOLDOUT46, **HOLDOUT47,
       **HOLDOUT48, **HOLDOUT49, **HOLDOUT50, **HOLDOUT51, **HOLDOUT52, **HOLDOUT53, **HOLDOUT54,
       **HOLDOUT55, **HOLDOUT56, **HOLDOUT57, **HOLDOUT58, **HOLDOUT59}

__all__ = ["FAMILIES", "Record", "family", "TUNING", "HOLDOUT", "HOLDOUT2", "HOLDOUT3", "HOLDOUT4",
           "HOLDOUT5", "HOLDOUT6", "HOLDOUT7", "HOLDOUT8", "HOLDOUT9", "HOLDOUT10", "HOLDOUT11",
           "HOLDOUT12", "HOLDOUT13", "HOLDOUT14", "HOLDOUT15", "HOLDOUT16", "HOLDOUT17", "HOLDOUT18",
           "HOLDOUT19", "HOLDOUT20", "HOLDOUT21", "HOLDOUT22", "HOLDOUT23", "HOLDOUT24", "HOLDOUT25", "HOLDOUT26",
           "HOLDOUT27", "HOLDOUT28", "HOLDOUT29", "HOLDOUT30", "HOLDOUT31", "HOLDOUT32",
           "HOLDOUT33", "HOLDOUT34", "HOLDOUT35", "HOLDOUT36", "HOLDOUT37", "HOLDOUT38", "HOLDOUT39", "HOLDOUT40",
           "HOLDOUT41", "HOLDOUT42", "HOLDOUT43", "HOLDOUT44", "HOLDOUT45", "HOLDOUT46", "HOLDOUT47", "HOLDOUT48",
           "HOLDOUT49", "HOLDOUT50", "HOLDOUT51", "HOLDOUT52", "HOLDOUT53", "HOLDOUT54",
           "HOLDOUT55", "HOLDOUT56", "HOLDOUT57", "HOLDOUT58", "HOLDOUT59", "ALL"]
