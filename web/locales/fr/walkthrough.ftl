# Le parcours de conception (web/teaching/walkthrough*.js) : le titre de chaque section, son texte,
# ses notes, sa figure, les titres de ses tracés et les étiquettes de leurs signaux, la loi propre
# de l’étape, le rapport de stabilité et la comparaison des prédicteurs de l’EKF.

## Section model (walkthrough-text.js) : 1. Le modèle du moteur (2)

walkthrough-model-title = 1. Le modèle du moteur (2)
walkthrough-model-prose-1 = L’état comprend la vitesse du rotor ω = x1, les courants statoriques i_sa, i_sb = x2, x3 et les flux rotoriques φ_ra, φ_rb = x4, x5 dans le repère fixe a–b. Seuls les courants sont mesurés ; les tensions u1, u2 sont les entrées.
walkthrough-model-prose-2 = Le couple divisé par l’inertie vaut a1(x3·x4 − x2·x5), en rad/s² : le produit vectoriel du courant et du flux (a1 = 3n_pM/(2JL_r) contient déjà 1/J ; multipliez donc par J pour obtenir des N m). La charge a2 + a3·x1 correspond au couple constant T0 et au frottement Cf·ω, divisés par J. Les paramètres regroupés ci-dessous sont calculés par le cœur de simulation à partir des paramètres du moteur utilisés ; le moteur simulé et le modèle (ce que supposent l’EKF et le correcteur) peuvent différer.
walkthrough-model-note = Le σ est ici en henrys : le σ = L_s − M²/L_r de l’article est l’inductance de fuite totale vue du stator (l’inductance transitoire), et non la fuite propre du stator L_s − M ; beaucoup d’ouvrages écrivent plutôt le coefficient de dispersion sans dimension σ = 1 − M²/(L_sL_r).
walkthrough-model-plot-title = Vitesse et flux

## Section ekf (walkthrough-text.js) : 2. Le filtre de Kalman étendu (10)–(20)

walkthrough-ekf-title = 2. Le filtre de Kalman étendu (10)–(20)
walkthrough-ekf-prose-1 = L’EKF estime les cinq états à partir des courants mesurés et des tensions appliquées. Il prédit avec le modèle discrétisé par Euler explicite (10), linéarisé par la jacobienne (11), et corrige avec l’innovation : les courants mesurés moins les courants prédits.
walkthrough-ekf-prose-2 = Q (bruit de processus : q·Ts sur chaque état, plus q_speed·Ts sur la seule vitesse) dit à quel point on se fie au modèle ; R (bruit de mesure, r_std²·I), à quel point on se fie aux capteurs. Un seul q pour des états d’unités différentes est le choix de l’article ; q_speed laisse l’estimée de vitesse varier sans relâcher le reste. Le gain K_k entre dans le correcteur comme gain d’observateur L = K_k/Ts de la forme générale (4) : les erreurs d’estimation x̃ sont ce que le correcteur doit tolérer.
walkthrough-ekf-prose-3 = Un filtre cohérent a ses innovations dans leur bande ±2σ environ 95 % du temps et une innovation normalisée au carré (NIS) de moyenne 2. Dans ce parcours, les plages et les bornes portent sur { $wt-ekf-euler-nis--draws } tirages de bruit (graines 1 à { $wt-ekf-euler-nis--draws }). Le prédicteur d’Euler ne peut pas suivre des courants à 200 Hz : sur sine200, son NIS moyen vaut au moins { $wt-ekf-euler-nis } sur chaque tirage, celui du prédicteur RK4 au plus { $wt-ekf-rk4-nis } ; comparez-les ci-dessous.
walkthrough-ekf-prose-4 = La section 3.1 de l’article cite un remède qu’elle ne construit pas : traiter les grandeurs lentement variables comme des états supplémentaires. Le réglage ekf.load ajoute a2 = T_L0/J sous forme de marche aléatoire (le correcteur utilise alors â2 et sa dérivée, l’injection l_a·(x̃2, x̃3)) ; ekf.rr ajoute la résistance rotorique (les a5, a7, a8, a10 du correcteur suivent R̂_r). Les deux derniers tracés montrent ces deux estimées avec leurs bandes ±2σ tirées de P, face aux valeurs réelles. Un état supplémentaire absorbe tout ce qui manque au modèle, à bon ou à mauvais escient : un état de résistance rotorique soumis à une charge inconnue prend la charge pour une résistance (voir les leçons).
walkthrough-ekf-note = L’équation (13) imprimée prédit avec u_{"{"}k|k−1{"}"} ; la tension qui a agi pendant le dernier échantillon est u_{"{"}k−1{"}"}, celle qu’utilise (10) et qu’utilise aussi le filtre ici. La forme de Joseph écrit la mise à jour de la covariance (19) comme une somme de deux termes symétriques, chacun semi-défini positif pour tout gain K : les arrondis risquent bien moins de faire perdre l’une ou l’autre de ces propriétés à P qu’avec la forme courte (I − K_kC)P_{"{"}k|k−1{"}"}, sans que rien ne le garantisse.
walkthrough-ekf-plot-title = Innovation ỹ_a avec sa bande ±2σ tirée de S_k
walkthrough-ekf-plot4-title = Innovation normalisée au carré avec sa bande à 95 % (χ², 2 ddl)
walkthrough-ekf-plot2-title = Estimée de vitesse et sa variance
walkthrough-ekf-plot3-title = Module du flux : réel et estimé
walkthrough-ekf-plot5-title = Couple de charge : estimée â2·J avec sa bande ±2σ, et valeur réelle
walkthrough-ekf-plot6-title = Résistance rotorique : estimée avec sa bande ±2σ, et celle du moteur

## Section bridge (walkthrough-text.js) : 3. De l’observateur au correcteur : (4) et (5)

walkthrough-bridge-title = 3. De l’observateur au correcteur : (4) et (5)
walkthrough-bridge-prose-1 = Le correcteur ne voit jamais l’état du moteur, seulement l’estimée x̂ de l’observateur et les courants mesurés x2, x3. Notons x̃ = x − x̂ l’erreur d’estimation. Deux de ses composantes sont mesurées : les résidus de courant x̃2 = x2 − x̂2 et x̃3 = x3 − x̂3. Trois ne le sont pas : l’erreur de vitesse x̃1 et les erreurs de flux x̃4, x̃5.
walkthrough-bridge-prose-2 = L’article conçoit le correcteur pour un observateur de la forme générale (4) : le modèle (2) recopié avec les estimées, plus une injection si_i = l_i1·x̃2 + l_i2·x̃3 (5), une correction qui tire chaque estimée en fonction des résidus mesurés. Lue comme un pas d’Euler explicite, la mise à jour de l’EKF a cette forme, avec L = K_k/Ts et le résidu a priori y_k − Cx̂_{"{"}k|k−1{"}"} (15), pour les lignes 2 à 5. Pour la ligne 1, seulement à peu près : le terme de couple de l’EKF lit les courants estimés x̂2, x̂3 là où (4) lit les courants mesurés x2, x3. Le correcteur utilise ici le résidu a posteriori y_k − Cx̂_{"{"}k|k{"}"} = (I − CK_k)(y_k − Cx̂_{"{"}k|k−1{"}"}), qui correspond à x̃ = x − x̂ pour l’estimée a posteriori x̂_{"{"}k|k{"}"} qu’il utilise ; les deux ne concordent que tant que CK_k reste petit.
walkthrough-bridge-prose-3 = Soustraire (4) de (2) donne la dynamique d’erreur ci-dessous. Le correcteur dérive les résidus mesurés (ils figurent dans v1 et dans ψ3), et leurs dérivées contiennent les erreurs non mesurées x̃1, x̃4, x̃5. Chacune de ces dérivées est scindée en deux : la dynamique nominale des résidus, c’est-à-dire ce que vaudraient ẋ̃2 et ẋ̃3 avec x̃1 = x̃4 = x̃5 = 0, que le correcteur calcule, et le reste, qu’il ne peut pas calculer. La conception suppose aussi L constant : L̇ est négligé partout dans la suite.
walkthrough-bridge-prose-4 = C’est la conception intégrée qui donne son titre à l’article : la dynamique d’erreur de l’observateur fait partie de la conception du correcteur, et les termes inconnus n’apparaissent que là où l’on dérive un courant mesuré ou un résidu, à l’étape 2 (ż2 contient ẋ2, ẋ3 et v̇1) et à l’étape 4 (ż4 contient les dérivées des injections si4, si5). Les étapes 1 et 3 n’en ont aucun. Là où ils apparaissent, ils sont regroupés dans d̃2 et d̃4 et traités comme des perturbations bornées. Avec un modèle exact, ce sont les seuls ; un modèle qui diffère du moteur ajoute à ż2 et ż4 ses propres termes, que les d̃2 et d̃4 de l’article ne contiennent pas.
walkthrough-bridge-prose-5 = Ce que l’intégration remplace, c’est la séparation des échelles de temps que cite le résumé de l’article : un observateur rendu tellement plus rapide que le correcteur que celui-ci peut traiter son estimée comme l’état. Les lois ci-dessous mettent encore x̂ là où une loi de retour d’état mettrait x, selon le principe d’équivalence certaine ; ce qu’ajoute la conception, c’est que les erreurs d’estimation entrent dans son argument de Lyapunov, sous forme de d̃2 et d̃4 bornés sous l’hypothèse 4.2, au lieu d’être supposées nulles.
walkthrough-bridge-figure = Le correcteur et l’observateur, comme sur la fig. 1 de l’article : le correcteur ne voit le moteur qu’à travers l’estimée, le gain et les résidus de l’EKF, et les courants mesurés.
    .alt = Schéma fonctionnel : la consigne ainsi que l’estimée, le gain et les résidus de l’EKF entrent dans le correcteur par backstepping ; sa tension passe par la limite de tension et alimente le moteur ; les courants mesurés et la tension appliquée reviennent dans l’EKF.
walkthrough-bridge-note = L’article écrit si_i(x̃2, x̃3) pour l’injection ; ici, si_i désigne sa valeur l_i1·x̃2 + l_i2·x̃3. La lettre ψ désigne à la fois la cible de flux ψ_d et les termes connus ψ2, ψ3, ψ4 des étapes ci-dessous : ils n’ont aucun rapport.

## Section step1 (walkthrough-text.js, walkthrough-laws.js) : 4. Étape 1 : la boucle de vitesse

walkthrough-step1-title = 4. Étape 1 : la boucle de vitesse
walkthrough-step1-prose-1 = L’étape 1 régule la vitesse estimée : z1 = x̂1 − ω_d. Sa dérivée, tirée de la première ligne de (4), est la boucle ouverte (23). Décomposez le terme de frottement autour de la consigne, −a3·x̂1 = −a3·z1 − a3·ω_d : l’amortissement propre du moteur −a3·z1 reste, et −a3·ω_d est un terme connu.
walkthrough-step1-prose-2 = Une commande virtuelle est un signal qu’une étape traite comme son entrée, bien que le moteur n’ait pas d’entrée de ce genre. Celle de l’étape 1 est le terme de couple a1(x3·x̂4 − x2·x̂5), construit à partir des courants mesurés et des flux estimés : on lui demande d’égaler v1 (un couple divisé par l’inertie, en rad/s²) et on nomme z2 l’écart (24). On a alors (25).
walkthrough-step1-prose-3 = Choisissez v1 = v1a + v1s (26). Le terme d’anticipation v1a (27) compense tous les termes connus ; si1 est connu, puisqu’il n’utilise que les résidus mesurés. Le retour v1s = −k1s1·z1 (28) laisse (29), ż1 = −k1·z1 + z2 avec k1 = a3 + k1s1 : k1s1 est la part du taux k1 que le correcteur ajoute à l’amortissement propre a3 du moteur, si bien que v1a contient a3·ω_d et non a3·x̂1. Les étapes 1 et 2 conservent l’amortissement propre du moteur ; les étapes 3 et 4 compensent tout ce qu’elles connaissent.
walkthrough-step1-prose-4 = La fonction de Lyapunov de l’étape 1 est V1 = ½z1². Le long de (29), V̇1 = z1ż1 = −k1z1² + z1z2 : négative, au terme croisé z1z2 près, que l’étape 2 compense.
walkthrough-step1-prose-5 = L’étape 2 a besoin de v̇1. Dérivez (30) avec L constant (L̇ négligé) : la dérivée de l’injection est l11·ẋ̃2 + l12·ẋ̃3, et ẋ̃2, ẋ̃3 contiennent les erreurs non mesurées x̃1, x̃4, x̃5 (section 3). La partie connue de v̇1 met à leur place la dynamique nominale des résidus ; le reste, les « … » ci-dessous, va dans d̃2.
walkthrough-step1-note = L’équation (31) imprimée porte a3·ω_d et â2 là où il faut a3·ω̇_d et dâ2/dt (corrigé ci-dessus). Les « … » sont les termes en x̃1, x̃4, x̃5 : −(l11·a5 − l12·a6·x̂1)·x̃4 − (l12·a5 + l11·a6·x̂1)·x̃5 − (l11·a6·x5 − l12·a6·x4)·x̃1.
walkthrough-step1-plot-title = Étape 1 : z1, v1 = v1a + v1s et le terme de couple
walkthrough-step1-plot3-title = Étape 1 : ż1 tel que la simulation l’a produit (sa variation sur chaque échantillon, divisée par Ts) face au −k1·z1 + z2 voulu
walkthrough-law-1-intro = Établissez vous-même v1 et écrivez-la ci-dessous sous forme de formule des noms de cette section (x1h pour x̂1, wd et dwd pour ω_d et ω̇_d, si1, a2, a3, k1s1, z1 ; la liste complète est plus bas), avec + − * / ^, des parenthèses et des fonctions. Elle s’exécute à 20 kHz à la place de la loi (26) de l’article dès que vous appuyez sur Entrée ou marquez une pause dans la saisie ; un champ vide rétablit la loi de l’article. Après la simulation, le verdict confronte votre loi à la dynamique voulue ż1 = −k1·z1 + z2 en des états et des valeurs de paramètres tirés au hasard, et le tracé ci-dessous montre son résidu sur toute la simulation : nul pour une loi qui donne cette dynamique.
walkthrough-law-1-plot-title = Étape 1 : résidu de votre loi, ż1 face au ż1 = −k1·z1 + z2 voulu (votre v1 moins celle de l’article)

## Section step2 (walkthrough-text.js, walkthrough-laws.js) : 5. Étape 2 : la boucle de couple

walkthrough-step2-title = 5. Étape 2 : la boucle de couple
walkthrough-step2-prose-1 = L’étape 2 fait suivre v1 au terme de couple en amenant z2 à zéro, et c’est ici que les tensions apparaissent pour la première fois. Dérivez (24) : ẋ2 et ẋ3 apportent bu1 et bu2, si bien que v2 = b·a1(x̂4·u2 − x̂5·u1) est l’entrée ; x̂̇4, x̂̇5 sont ceux de (4) ; et −v̇1 est donné par (31). Regroupez dans ψ2 ce que connaît le correcteur, et écrivez le terme de couple sous la forme z2 + v1 : on obtient (32).
walkthrough-step2-prose-2 = ψ2 rassemble tout ce qui est connu : les dynamiques du flux et du courant, les injections si4, si5 et la partie connue de v̇1. Les erreurs non mesurées x̃1, x̃4, x̃5 n’entrent que par d̃2 (33) (avec un modèle exact ; un modèle qui diffère du moteur ajoute ses propres termes à ż2) : ce terme est linéaire en elles, avec des coefficients construits à partir de x̂, x et L, donc borné tant que x̂, x, L et x̃ le sont. L’article maintient x̂ borné par une projection (7)–(9) ; celle-ci borne x̂, et non x̃, et tant que la projection agit, x̂̇ n’est plus donné par (4), et ψ2–ψ4 ne sont plus exacts. L’EKF utilisé ici n’a pas de projection : rien d’autre que la simulation elle-même ne borne x̂.
walkthrough-step2-prose-3 = Choisissez v2 = v2a + v2s (34) : v2a = −ψ2 − z1 compense les termes connus et le terme croisé z1z2 de V̇1 ; v2s = −k2s1·z2 + v2s2 (36) ajoute le retour, avec k2 = a7 + a8 + k2s1, puisque le moteur fournit lui-même l’amortissement a7 + a8. Pour le moteur de l’article, a7 + a8 = 232,7 /s, donc k2s1 = 967,3 /s lorsque k2 = 1200 /s.
walkthrough-step2-prose-4 = Le terme robuste v2s2 = −h2²z2/(4ε2) (38) domine d̃2 si h2 borne |d̃2|. Avec V_s2 = ½(z1² + z2²) (39), V̇_s2 = −k1z1² − k2z2² + z2(v2s2 + d̃2) ≤ −k1z1² − k2z2² + ε2 (40). Aucun h2 fini n’y parvient pour un d̃2 qui croît sans limite : dès que |d̃2| dépasse h2, z2(v2s2 + d̃2) peut dépasser ε2.
walkthrough-step2-prose-5 = Le choix des termes qui vont dans d̃2 est libre : (33) écrit la vitesse réelle sous la forme x1 = x̂1 + x̃1 et garde la partie en x̂1 dans ψ2 ; une autre répartition déplacerait des termes entre ψ2 et d̃2 sans changer ż2. C’est sur l’hypothèse 4.2 (22) que l’article s’appuie ici : elle suppose que x̃ reste dans un pavé connu [x̃_min, x̃_max], affirme que d̃2 est alors borné et prend cette borne pour h2 (38), comme l’étape 4 le fait pour h4 (53). Elle ne donne aucune valeur pour le pavé ni pour les bornes. Ici, h2 et h4 sont des réglages ; le tracé de d̃2 ci-dessous et celui de d̃4 à l’étape 4 mesurent ces termes sur la simulation affichée, ce qui est une façon de les dimensionner pour cette simulation. ε2 arbitre ensuite entre le plancher ε/λ de (59) et le taux h2²/(4ε2) que v2s2 ajoute à celui de z2, et une boucle échantillonnée toutes les Ts ne tient un taux que bien en dessous d’environ 2/Ts ; la leçon « Les termes robustes et la borne (59) » détaille un choix.
walkthrough-step2-prose-6 = Dériver z2 donne aussi −(a7 + a8)·z2, l’amortissement propre du moteur ; (32) tel qu’imprimé l’omet, et le k2 = a7 + a8 + k2s1 de (36) en tient compte.
walkthrough-step2-note = L’équation (35) imprimée est v2a = −ψ2 − d̃2 − z1 : d̃2 est inconnu, aucun correcteur ne peut donc le soustraire ; le correcteur utilise ici −ψ2 − z1 et laisse d̃2 au terme robuste.
walkthrough-step2-shows-1 = Le tracé ci-dessous évalue d̃2 à partir de la vérité simulée : le ż2 effectif du moteur moins les termes que connaît le correcteur, avec les courants réels à la place des courants mesurés. Il est évalué pour l’EKF à cinq états sans compensation du retard ; pour un observateur à états supplémentaires (ekf.load, ekf.rr) ou avec delay.comp, le tracé reste vide. h2 doit valoir au moins la crête de |d̃2| pour que (38) le domine : lisez-la sur step avec un modèle exact, puis avec une erreur de modèle (plant.j, plant.rr). Avec la R_r du moteur 10 % au-dessus de celle du modèle (plant.rr = 5.445), la boucle diverge ou échoue sur { $wt-rrhigh-runaway } des { $wt-rrhigh-runaway--draws } tirages : le flux part à la dérive sur { $wt-rrhigh-off } d’entre eux et le correcteur échoue avant la fin sur { $wt-rrhigh-fail }. Le flux termine les 0,1 s du préréglage entre { $wt-rrhigh-flux-min } et { $wt-rrhigh-flux-max } Wb et vaut { $wt-rrhigh1s-flux-min } à { $wt-rrhigh1s-flux-max } Wb après 1 s, et les coefficients de d̃2 dans (33) croissent avec x.
walkthrough-step2-plot-title = Étape 2 : z2 et v2 = v2a + v2s
walkthrough-step2-plot2-title = Étape 2 : d̃2 évalué à partir de la vérité simulée, face à ±h2
walkthrough-step2-plot3-title = Étape 2 : ż2 tel que la simulation l’a produit (sa variation sur chaque échantillon, divisée par Ts) face au −k2·z2 − z1 voulu (avec son terme robuste quand robust=1)
walkthrough-law-2-intro = Établissez vous-même v2 et écrivez-la ci-dessous sous forme de formule des noms de cette section (v1 et z2 (de l’étape 1), x2 et x3, x4h et x5h, si4 et si5, dxt2 et dxt3, l11 et l12, ddwd, a1 à a10, k1, k1s1, k2s1 ; la liste complète est plus bas), avec + − * / ^, des parenthèses et des fonctions. Elle s’exécute à 20 kHz à la place de la loi (34) de l’article dès que vous appuyez sur Entrée ou marquez une pause dans la saisie ; un champ vide rétablit la loi de l’article. Si vous avez écrit votre propre v1 sous l’étape 1, votre v2 est jugée sur celle-ci : elle doit dériver votre v1, avec le ż1 que donne votre v1. Après la simulation, le verdict confronte votre loi à la dynamique voulue ż2 = −k2·z2 − z1 en des états et des valeurs de paramètres tirés au hasard, et le tracé ci-dessous montre son résidu sur toute la simulation : nul pour une loi qui donne cette dynamique.
walkthrough-law-2-plot-title = Étape 2 : résidu de votre loi, ż2 face au ż2 = −k2·z2 − z1 voulu (votre v2 moins la v2 qui le donne : celle de l’article ou, après votre propre v1, celle qui dérive la vôtre)

## Section step3 (walkthrough-text.js, walkthrough-laws.js) : 6. Étape 3 : la boucle externe de flux

walkthrough-step3-title = 6. Étape 3 : la boucle externe de flux
walkthrough-step3-prose-1 = L’étape 3 régule le carré du module du flux estimé : z3 = x̂4² + x̂5² − ψ_d (42). Sa dérivée ne demande que (4) : ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5 − ψ̇_d, où les termes en a9 se compensent, et qui est écrite ci-dessous avec les seules estimées. Écrire x̂2 = x2 − x̃2 et x̂3 = x3 − x̃3 sépare de ψ3 (43) la commande virtuelle 2a10(x2·x̂4 + x3·x̂5), la part de ż3 que pilotent les courants statoriques.
walkthrough-step3-prose-2 = ψ3 ne dépend que d’estimées et de résidus mesurés, si bien que l’étape 3 n’a aucun terme inconnu : avec v3 = −ψ3 − k3·z3 (45), ż3 = −k3·z3 + z4 (46) est exacte en temps continu, pour l’estimée de flux propre à l’observateur. Sa fonction de Lyapunov est V3 = ½z3², avec V̇3 = −k3z3² + z3z4 ; l’étape 4 compense le terme croisé.
walkthrough-step3-prose-3 = Comme v3 = −ψ3 − k3·z3, l’erreur suivante z4 (44) vaut z4 = ż3 + k3·z3 : ce qui manque à z3 pour décroître au taux k3.
walkthrough-step3-prose-4 = L’article écrit le retour sous la forme v3s = −k3s1·z3 et pose k3 = k3s1 (46) : v3a compense tout ψ3, y compris la décroissance propre du flux −2a8·(x̂4² + x̂5²), si bien que tout le taux k3 vient du correcteur, alors qu’à l’étape 1 l’amortissement a3 du moteur fait partie de k1.
walkthrough-step3-note = L’énoncé du problème demande que x4² + x5² suive ψ_d², mais (42) soustrait ψ_d : ψ_d est ici la cible du carré du module, en Wb². Le psi_d du scénario est cette cible : psi_d = 0.5 Wb² demande un module de flux |φ| = 0,707 Wb. Les simulations de l’article posent « ϕ_d = 0,5 » comme module de flux voulu, ce qui, pris à la lettre, fait 0,5 Wb (0,25 Wb²) ; les préréglages le prennent comme le carré du module, comme l’utilise (42), soit le carré du flux initial de l’article [0,5 ; 0,5].
walkthrough-step3-shows-1 = Le tracé de z3 montre l’erreur de l’estimée de flux propre à l’observateur par rapport à la cible, et non celle du moteur. Sur step avec un modèle exact, à partir de 15 ms, sa valeur RMS vaut { $wt-z3-min } à { $wt-z3-max } mWb² avec l’EKF et { $wt-z3-quiet } mWb² sans bruit de mesure (noise=0) : le bruit entre dans z3 par les innovations. Avec l’observateur parfait (perfect=1), dont l’estimée est le flux du moteur, elle reste sous { $wt-z3-perfect-max } mWb².
walkthrough-step3-plot-title = Étape 3 : z3 et v3 = v3a + v3s
walkthrough-step3-plot3-title = Étape 3 : ż3 tel que la simulation l’a produit (sa variation sur chaque échantillon, divisée par Ts) face au −k3·z3 + z4 voulu
walkthrough-law-3-intro = Établissez vous-même v3 et écrivez-la ci-dessous sous forme de formule des noms de cette section (x4h et x5h, xt2 et xt3, si4 et si5, a8, a10, k3, z3 ; la liste complète est plus bas), avec + − * / ^, des parenthèses et des fonctions. Elle s’exécute à 20 kHz à la place de la loi (45) de l’article dès que vous appuyez sur Entrée ou marquez une pause dans la saisie ; un champ vide rétablit la loi de l’article. Après la simulation, le verdict confronte votre loi à la dynamique voulue ż3 = −k3·z3 + z4 en des états et des valeurs de paramètres tirés au hasard, et le tracé ci-dessous montre son résidu sur toute la simulation : nul pour une loi qui donne cette dynamique.
walkthrough-law-3-plot-title = Étape 3 : résidu de votre loi, ż3 face au ż3 = −k3·z3 + z4 voulu (votre v3 moins celle de l’article)

## Section step4 (walkthrough-text.js, walkthrough-laws.js) : 7. Étape 4 : la boucle interne de flux et les tensions

walkthrough-step4-title = 7. Étape 4 : la boucle interne de flux et les tensions
walkthrough-step4-prose-1 = L’étape 4 amène z4 à zéro ; son entrée v4 = 2a10·b(x̂4·u1 + x̂5·u2) est la seconde combinaison des tensions. Comme z4 = ż3 + k3·z3, ż4 = z̈3 + k3·ż3 = z̈3 + k3(−k3z3 + z4). Dérivez ż3 une fois de plus sous sa forme écrite avec les seules estimées (la première ligne de l’étape 3), et non sous la forme (43), dont les courants mesurés apporteraient des termes inconnus qui se compensent : les termes en x̂̇4, x̂̇5 se regroupent comme ci-dessous, x̂̇2 et x̂̇3 apportent les tensions (v4) et la dynamique des courants, et les dérivées des injections l41·ẋ̃2 + l42·ẋ̃3 et l51·ẋ̃2 + l52·ẋ̃3 apportent les dérivées des résidus.
walkthrough-step4-prose-2 = Dans la dérivée de 2a10·(x2·x̂4 + x3·x̂5), les termes en a6 de ẋ2 et ẋ3 (2) se compensent dans leur partie connue, a6·x̂1·(x̂4·x̂5 − x̂5·x̂4) = 0, ce qui explique l’absence de a6 dans ψ4 ; le reste, qui contient x̃1, x̃4, x̃5, va dans d̃4. Avec V_s4 = ½z3² + ½z4² (56), V̇_s4 = −k3z3² − k4z4² + z4(v4s2 + d̃4) ≤ −λ4·V_s4 + ε4 avec λ4 = 2·min(k3, k4), ce qui s’intègre en (57), comme le fait la section 8 pour V.
walkthrough-step4-prose-3 = ψ4 prend la dynamique nominale des résidus pour ẋ̃2 et ẋ̃3 (section 3), avec L̇ négligé : la (47) imprimée est valable avec L̇ = 0. Ce que la dynamique nominale laisse de côté, les termes en x̃1, x̃4, x̃5 de ẋ̃2 et ẋ̃3 pondérés par 2(l41·x̂4 + l51·x̂5) et 2(l42·x̂4 + l52·x̂5), constitue d̃4.
walkthrough-step4-prose-4 = Choisissez v4 = −ψ4 − z3 − k4·z4 + v4s2 (49)–(51) : le −z3 compense le terme croisé z3z4 de V̇3, et l’on obtient (52). Ensemble, v2 et v4 fixent les deux tensions par la matrice de découplage (54), inversible tant que le flux estimé n’est pas nul (55). La limite de tension agit ensuite : l’article ne donne qu’une limite de 400 V ; le carré (vlimit=box) écrête chaque composante à ±400 V, tandis que le cercle et l’hexagone de l’onduleur (vlimit) réduisent le vecteur entier en conservant sa direction. Tant qu’elle agit, la dynamique d’erreur voulue n’est plus respectée.
walkthrough-step4-note = L’équation (48) imprimée porte a21, a22 là où il faut a41, a42 (corrigé ci-dessus). Le ψ4 ci-dessus est la (47) imprimée, regroupée : l’article écrit 2a10(l21·x̃2·x̂4 + …) pour 2a10(x̂4·si2 + x̂5·si3), et scinde en deux chaque produit en x̂̇4, x̂̇5. Son d̃4 est le même que celui imprimé, terme à terme.
walkthrough-step4-shows-1 = |d̃4|, évalué à partir de la vérité simulée comme d̃2, est tracé ci-dessous face à ±h4 ; h4 doit valoir au moins sa crête pour que (53) le domine.
walkthrough-step4-shows-2 = Pendant ses 5 premières ms, le transitoire de démarrage commande des tensions bien au-delà de la limite : la u_sa commandée culmine entre { $wt-cmd-step-min } et { $wt-cmd-step-max } V sur step et entre { $wt-cmd-rr-min } et { $wt-cmd-rr-max } V sur rr-mismatch (le préréglage de l’écart de résistance), et sur rr-mismatch la limite écrête la commande jusqu’à un instant compris entre { $wt-clip-rr-min } et { $wt-clip-rr-max } ms. Les tracés ajustent leurs axes y à la simulation qui suit ce transitoire ; décochez « Ajuster les axes y après le transitoire de démarrage » au-dessus des tracés pour le voir.
walkthrough-step4-plot-title = Étape 4 : z4, v4 et la tension avant et après la limite
walkthrough-step4-plot2-title = Étape 4 : d̃4 évalué à partir de la vérité simulée, face à ±h4
walkthrough-step4-plot3-title = Étape 4 : ż4 tel que la simulation l’a produit (sa variation sur chaque échantillon, divisée par Ts) face au −k4·z4 − z3 voulu (avec son terme robuste quand robust=1)
walkthrough-law-4-intro = Établissez vous-même v4 et écrivez-la ci-dessous sous forme de formule des noms de cette section (v3 et z4 (de l’étape 3), dx4h et dx5h, dxt2 et dxt3, si2 à si5, l41 à l52, a5, a7, a8, a10, k3, k4, z3 ; la liste complète est plus bas), avec + − * / ^, des parenthèses et des fonctions. Elle s’exécute à 20 kHz à la place de la loi (49) de l’article dès que vous appuyez sur Entrée ou marquez une pause dans la saisie ; un champ vide rétablit la loi de l’article. Si vous avez écrit votre propre v3 sous l’étape 3, votre v4 est jugée sur celle-ci : elle doit dériver votre v3, avec le ż3 que donne votre v3. Après la simulation, le verdict confronte votre loi à la dynamique voulue ż4 = −k4·z4 − z3 en des états et des valeurs de paramètres tirés au hasard, et le tracé ci-dessous montre son résidu sur toute la simulation : nul pour une loi qui donne cette dynamique.
walkthrough-law-4-plot-title = Étape 4 : résidu de votre loi, ż4 face au ż4 = −k4·z4 − z3 voulu (votre v4 moins la v4 qui le donne : celle de l’article ou, après votre propre v3, celle qui dérive la vôtre)

## Section stability (walkthrough-text.js) : 8. Stabilité : théorème 4.6

walkthrough-stability-title = 8. Stabilité : théorème 4.6
walkthrough-stability-prose-1 = Avec V = ½(z1² + z2² + z3² + z4²) (58), les quatre dynamiques d’erreur voulues donnent V̇ = −k1z1² − k2z2² − k3z3² − k4z4² + z2(v2s2 + d̃2) + z4(v4s2 + d̃4) (60). Les termes croisés ±z1z2 et ±z3z4 se compensent : c’est à cela que servent le −z1 de v2a et le −z3 de v4a.
walkthrough-stability-prose-2 = Trois lignes achèvent la démonstration. Premièrement, si |d̃2| ≤ h2 (h2 = δ_d2 de (38), une borne de d̃2 dont l’article affirme l’existence compte tenu des bornes sur x̃ de l’hypothèse 4.2 (22), sans l’établir : d̃2 est linéaire en x̃1, x̃4, x̃5 avec des coefficients qui contiennent les valeurs réelles x1, x4, x5, les estimées et les gains l11, l12, si bien que des bornes sur x̃ ne le bornent que tant que ces grandeurs restent bornées), l’inégalité de Young borne le couple robuste : z2(v2s2 + d̃2) ≤ h2|z2| − h2²z2²/(4ε2) ≤ ε2, puisque la différence est un carré parfait. Il en va de même pour z4 avec h4 et ε4. Deuxièmement, Σk_i·z_i² ≥ min(k_i)·Σz_i² = 2·min(k_i)·V = λV. Donc V̇ ≤ −λV + ε avec ε = ε2 + ε4. Troisièmement, le lemme de comparaison : e^(λt)·V a pour dérivée e^(λt)·(V̇ + λV) ≤ ε·e^(λt) ; en intégrant de 0 à t, on obtient (59).
walkthrough-stability-prose-3 = V additionne des carrés d’unités différentes (z1 en rad/s, z2 en rad/s², z3 en Wb², z4 en Wb²/s), et ε2 (rad²/s⁵) et ε4 (Wb⁴/s³) diffèrent aussi : (59) vaut pour les valeurs numériques en unités SI. Elle ne se transpose pas telle quelle à toute pondération : avec V = ½Σw_i·z_i², les termes croisés de V̇ deviennent (w1 − w2)·z1z2 et (w3 − w4)·z3z4, qui ne se compensent que pour w1 = w2 et w3 = w4 (des poids inégaux laissent un terme croisé, qui abaisse λ), à moins de remettre à l’échelle les couplages −z1 de (35) et −z3 de (50) en −(w1/w2)·z1 et −(w3/w4)·z3. Ces couplages portent une unité (1/s² en SI) que la somme simple masque. La borne porte sur la somme, et sur chaque ½z_i² seulement à travers la somme. Le tracé compare le V enregistré à cette borne pour cette simulation.
walkthrough-stability-prose-4 = Le théorème borne les erreurs z_i des estimées, et non le moteur : l’erreur de vitesse réelle vérifie |x1 − ω_d| ≤ |z1| + |x̃1|. Il suppose |d̃2| ≤ h2 et |d̃4| ≤ h4 sur toute la simulation ; ces bornes supposent elles-mêmes x, x̂ et L bornés, ce qui est justement la conclusion du théorème, et les termes en L̇ négligés ne figurent ni dans ψ ni dans d̃. Il ne dit rien du moteur réel lorsque l’hypothèse n’est pas satisfaite.
walkthrough-stability-shows-1 = Avec l’erreur initiale de 10 % de l’EKF et un modèle exact, la limite de tension fait tenir le démarrage : sine200 diverge sur { $wt-limit-runaway } des { $wt-limit-runaway--draws } tirages avec elle (avec la R_r du moteur 10 % au-dessus de celle du modèle, sur { $wt-limit-rrhigh-runaway } même avec elle), mais sans elle (vmax=100000) sur { $wt-nolimit-runaway }, en finissant avec un écart allant jusqu’à { $wt-nolimit-off-max } rad/s et un flux atteignant jusqu’à { $wt-nolimit-flux-max } Wb. À partir d’une estimée initiale correcte (init_err=0), la même simulation sans limite donne une erreur de poursuite de { $wt-exact-rms-min } à { $wt-exact-rms-max } rad/s RMS sur chaque tirage avec un modèle exact ; avec la R_r du moteur 10 % au-dessus de celle du modèle, elle échoue malgré tout : son erreur RMS vaut au moins { $wt-exact-rrhigh-rms } rad/s, et elle diverge sur { $wt-exact-rrhigh-runaway } des { $wt-exact-rrhigh-runaway--draws } tirages.
walkthrough-stability-plot-title = Fonction de Lyapunov V(t) = ½Σz_i² face à la borne (59), échelle logarithmique

## Les signaux des tracés, dans leurs légendes (walkthrough-text.js, walkthrough-laws.js)

walkthrough-series-estimated = { $signal } estimé
walkthrough-series-true = { $signal } réel
walkthrough-series-right = { $signal } (à droite)
walkthrough-series-right-unit = { $signal } ({ $unit }, à droite)
walkthrough-series-feedforward = { $term } (anticipation)
walkthrough-series-feedback = { $term } (retour)
walkthrough-series-run = { $signal }, simulation
walkthrough-series-designed = { $expression }, dynamique voulue
walkthrough-series-load-true = T_L réel (T0 + échelon)
walkthrough-series-rr-motor = R_r du moteur
walkthrough-series-u-commanded = u_sa commandée (V)
walkthrough-series-u-applied = u_sa appliquée (V)
walkthrough-series-lyapunov = V(t) fonction de Lyapunov
walkthrough-series-bound = borne (59)
walkthrough-series-law-paper = votre { $output } − la { $output } de l’article
walkthrough-series-law-gives = votre { $output } − la { $output } qui donne { $rate }
walkthrough-nis-low = quantile à 2,5 %
walkthrough-nis-high = quantile à 97,5 %
walkthrough-stability-plot-unit = V (unités mixtes : ½Σz_i²)

## Le cadre d’une section (walkthrough-sections.js, walkthrough.js)

walkthrough-diagram-label = Schéma de la section { $section }
walkthrough-equation-label = Équation { $number } de la section { $section }
walkthrough-run-shows = Ce que montre la simulation
walkthrough-lumped-label = Paramètres regroupés du moteur et du modèle
walkthrough-lumped-plant = moteur
walkthrough-lumped-model = modèle
walkthrough-stability-waiting = Lancez un scénario pour comparer V à la borne.
walkthrough-compare-button = Comparer les prédicteurs Euler et RK4 sur ce scénario
walkthrough-compare-label = Prédicteurs Euler et RK4 comparés
walkthrough-knobs = Réglages de conception
walkthrough-ifoc-note = Ce scénario exécute la base de comparaison classique, l’IFOC. Les termes du backstepping ci-dessous sont évalués à partir de l’estimée de l’EKF à titre de comparaison ; ce ne sont pas eux qui pilotent le moteur.
walkthrough-equations-failed = Les équations n’ont pas pu être chargées : vérifiez la connexion et rouvrez le parcours.

## Le rapport de stabilité (walkthrough-reports.js) : la borne (59) face à V sur la simulation,
## puis ce qu’il ajoute quand V sort de la borne, selon la cause probable. Ses phrases sont
## affichées l’une après l’autre, séparées par une espace.

walkthrough-stability-nothing = Rien n’a été enregistré.
walkthrough-stability-bound-robust = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (termes robustes actifs).
walkthrough-stability-bound-off = λ = 2·min(k) = { $lambda } 1/s, ε = { $eps } (termes robustes désactivés : la borne est donc V(0)·e^(−λt)).
walkthrough-stability-under =
    V reste sous la borne { $samples ->
        [one] en son seul échantillon
       *[other] sur les { $samples } échantillons
    }.
walkthrough-stability-above =
    V est au-dessus de la borne sur { $outside } { $samples ->
        [one] échantillon sur { $samples }
       *[other] des { $samples } échantillons
    }, la première fois à t = { $first } s ; { $outsideSaturated } d’entre eux ont la tension saturée ({ $saturated ->
        [one] { $saturated } échantillon est saturé en tout
       *[other] { $saturated } échantillons sont saturés en tout
    }).
walkthrough-stability-cause-saturation = La plupart de ces échantillons ont une tension commandée au-delà de la limite : la saturation rompt la dynamique d’erreur voulue sur laquelle repose la borne.
walkthrough-stability-cause-sampling = Avec l’observateur parfait et un modèle exact, d̃2 = d̃4 = 0, et en temps continu V resterait sous la borne (sur elle, avec des gains égaux). La boucle échantillonnée laisse une erreur qui lui est propre, de l’ordre de Ts sur les z_i : sur decay, V s’arrête à un plancher tandis que la borne continue de décroître, si bien que V finit bien au-dessus d’elle, et diviser Ts par deux multiplie ce plancher par { $wt-decay-halfts }. Une erreur de résistance rotorique ajoute une perturbation qui lui est propre, bien au-dessus de ce plancher : avec la R_r du moteur 10 % au-dessus et en dessous de celle du modèle, V termine decay à { $wt-decay-rrhigh } et { $wt-decay-rrlow } fois ce plancher. Une erreur d’inertie, elle, n’en ajoute pas sur decay : avec l’inertie du modèle 20 % au-dessus et en dessous de celle du moteur (model.j = 0.024 et model.j = 0.016), V finit à { $wt-decay-jhigh } et { $wt-decay-jlow } fois le plancher.
walkthrough-stability-cause-estimation-errors = Les erreurs d’estimation entrent sous forme de d̃2 et d̃4 ; avec les termes robustes désactivés, rien ne borne z2·d̃2 + z4·d̃4, si bien que la borne (qui suppose alors d̃ = 0) n’a pas de raison de tenir.
walkthrough-stability-cause-eps-or-sampling = ε est trop petit pour les d̃2, d̃4 effectifs, ou l’échantillonnage à 20 kHz ajoute une erreur que la démonstration en temps continu ne comporte pas.

## Les prédicteurs de l’EKF comparés (walkthrough-reports.js)

walkthrough-compare-note = Même scénario et même graine, seul le prédicteur de l’EKF diffère ; indicateurs à partir de t = { $from } s, fin du transitoire de démarrage, comme dans le bandeau des indicateurs.
walkthrough-compare-predictor = prédicteur
walkthrough-compare-tracking = RMS de poursuite (rad/s)
walkthrough-compare-speed = RMS de l’estimée de vitesse (rad/s)
walkthrough-compare-flux = RMS de l’estimée de flux (Wb)
walkthrough-compare-nis = NIS moyen
walkthrough-compare-saturated = échantillons à la limite de tension
