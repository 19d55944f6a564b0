# Les messages du cœur de simulation sur la loi propre d’une étape : pourquoi une formule a été
# refusée, et le verdict sur une loi face à la dynamique d’erreur que son étape doit donner. La CLI
# les dit en anglais d’après le fichier anglais ; la page, dans la langue du lecteur. Les noms (x1h,
# k1s1, v1, z2), les fonctions (sqrt), les formules (ż1 = −k1·z1 + z2, a3·ω_d), les réglages
# (law.v1), les numéros d’équation de l’article ((28)) et les saisies citées restent tels quels. Une
# saisie citée garde ses guillemets.

## Une formule refusée


## La loi propre d’une étape refusée ou absente


## Le verdict sur la loi propre d’une étape

# $designed : la dynamique d’erreur voulue (ż1 = −k1·z1 + z2) ; $output : la commande virtuelle
# que donne la loi (v1) ; $own vaut yes si l’étape est jugée sur la loi propre de l’étape
# précédente, $before (v1 ou v3) ; $worst : l’écart relatif (2e-16) ; $draws : le nombre d’états
# tirés ; $caveats : un message law-caveat-*.
law-designed = Votre étape { $step } donne la dynamique voulue { $designed }{ $own ->
        [yes] {" "}avec votre propre { $before } : votre { $output } est égale à celle qui donne cette dynamique
       *[no] : votre { $output } est égale à celle de l’article
    }, à { $worst } près en valeur relative, en { $draws } états et valeurs de paramètres tirés au hasard.{ $caveats }
# Comme law-designed ; $unit : l’unité de $output ; $difference : law-difference ou
# law-difference-unnamed.
law-not-designed = Votre étape { $step } ne donne pas la dynamique voulue { $designed }{ $own ->
        [yes] {" "}avec votre propre { $before } : votre { $output } ({ $unit }) diffère de celle qui donne cette dynamique
       *[no] : votre { $output } ({ $unit }) diffère de celle de l’article
    } d’un écart relatif allant jusqu’à { $worst }, en { $draws } états tirés au hasard. { $difference }{ $caveats }
# $cause : un des messages law-never-runs … law-not-finite.
law-not-designed-because = Votre étape { $step } ne donne pas la dynamique voulue { $designed } : { $cause }.
law-cannot-judge = Votre étape { $step } ne peut pas être jugée : { $cause }.
# $finding : un message law-term-*, law-mistake-*, law-scenario-values-only ou law-rate-of-z.
law-difference = La différence : { $finding }.
law-difference-unnamed = La différence n’est pas un seul terme de la loi de l’article : comparez votre loi à la dérivation de l’étape, terme à terme.

## Ce qu’un verdict ajoute après sa phrase (chaque réserve commence par l’espace qui suit la phrase)

law-caveat-none = {""}
# $names : les noms lus par la loi de l’étape précédente dont la dérivée est inconnue.
law-caveat-unchained = {" "}Votre { $before } lit { $names }, dont la boucle ne connaît pas la dérivée (elle contient la tension que choisit une étape ultérieure, ou une dérivée qui manque à la boucle) : cette étape est donc jugée sur la { $before } de l’article.
law-caveat-failed = {" "}Votre { $before } ne donne aucune valeur finie en { $failed } des { $draws } états tirés ; cette étape n’y est pas jugée.
# Les deux réserves : $unread est law-caveat-unchained, $failing law-caveat-failed.
law-caveat-both = { $unread }{ $failing }

## Pourquoi l’écart d’une loi à sa dynamique voulue n’est pas un nombre


## Ce qu’une loi fausse a de faux

# $term : un terme de la loi de l’article avec son signe (+a3·ω_d).
law-term = le terme { $term }
# $part : une partie du terme $term développé.
law-term-part = la partie { $part } du terme { $term }
# $label : law-term ou law-term-part.
law-term-missing = { $label } de la loi de l’article manque
law-term-wrong-sign = { $label } a le mauvais signe
law-term-twice = { $label } figure deux fois
# $factor : combien de fois le terme de l’article la loi contient.
law-term-scaled = { $label } vaut { $factor } fois ce qu’il faudrait
law-scenario-values-only = elle n’est égale à la loi de l’article qu’aux valeurs des paramètres et des gains de ce scénario : un paramètre ou un gain y est écrit par sa valeur là où la loi demande son nom
# La loi est celle de l’article moins (ou plus) $gain fois l’erreur $z de l’étape (z1) : $now est
# le taux auquel cette erreur décroît alors, $meant le taux voulu.
law-rate-of-z = c’est la loi de l’article { $sign ->
        [minus] moins
       *[plus] plus
    } { $gain }·{ $z } : avec les paramètres de ce scénario, votre { $z } décroît au taux de { $now } /s, et non de { $meant } /s ; vérifiez le gain et le signe de vos termes en { $z }

## Erreurs courantes des étudiants, nommées quand une loi en commet une

law-mistake-k1 = elle contient k1 là où (28) contient k1s1 = k1 − a3
law-mistake-a3-x1h = elle contient a3·x̂1 là où (27) contient a3·ω_d
law-mistake-k2 = elle contient k2 là où (36) contient k2s1 = k2 − a7 − a8 : le −(a7 + a8)·z2 de ż2 subsiste alors
law-mistake-printed-dv1 = elle prend v̇1 telle qu’imprimée dans (31), avec ses deux coquilles : a3·ω_d là où il faut sa dérivée a3·ω̇_d, et â2 là où il faut sa dérivée (0 pour une charge connue)
law-mistake-printed-dv1-wd = elle prend v̇1 telle qu’imprimée dans (31), avec a3·ω_d là où il faut sa dérivée a3·ω̇_d
law-mistake-printed-dv1-a2 = elle prend v̇1 telle qu’imprimée dans (31), avec â2 là où il faut sa dérivée (0 pour une charge connue)
law-mistake-robust-2 = elle écrit le terme robuste −h2²/(4·ε2)·z2 de (38) sans l’interrupteur robust : il agit donc même quand les termes robustes sont désactivés
law-mistake-psi-modulus = elle prend ψ_d pour le module du flux (ψ_d²), alors que le z3 = x̂4² + x̂5² − ψ_d de l’article en fait le carré du module
law-mistake-factor-2 = elle omet le facteur 2 dans tout ψ3 : la dérivée de x̂4² + x̂5² est 2·(x̂4·x̂̇4 + x̂5·x̂̇5)
law-mistake-residual-rates = elle omet les termes de dérivation en chaîne des résidus 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 et 2·(l42·x̂4 + l52·x̂5)·ẋ̃3 de ψ4
law-mistake-drifts = elle contient les dérives du modèle f̂4, f̂5 là où ψ4 contient les dérivées de l’observateur x̂̇4 = f̂4 + si4 et x̂̇5 = f̂5 + si5 : les injections sont omises
law-mistake-drift-4 = elle contient la dérive du modèle f̂4 là où ψ4 contient la dérivée de l’observateur x̂̇4 = f̂4 + si4 : l’injection si4 est omise
law-mistake-drift-5 = elle contient la dérive du modèle f̂5 là où ψ4 contient la dérivée de l’observateur x̂̇5 = f̂5 + si5 : l’injection si5 est omise
law-mistake-factor-si4 = le facteur de x̂̇4 omet si4 : la dérivée de 2·x̂4·si4 dans ψ3 donne 2·si4·x̂̇4
law-mistake-factor-si5 = le facteur de x̂̇5 omet si5 : la dérivée de 2·x̂5·si5 dans ψ3 donne 2·si5·x̂̇5
law-mistake-robust-4 = elle écrit le terme robuste −h4²/(4·ε4)·z4 de (53) sans l’interrupteur robust : il agit donc même quand les termes robustes sont désactivés

## Les noms qu’une loi peut utiliser : le sens de chacun (son nom, son symbole et son unité sont affichés à côté)

formula-name-x1h = vitesse du rotor estimée ω̂ (x̂1 a posteriori)
formula-name-x2h = courant statorique estimé î_sa
formula-name-x3h = courant statorique estimé î_sb
formula-name-x4h = flux rotorique estimé φ̂_ra
formula-name-x5h = flux rotorique estimé φ̂_rb
formula-name-x2 = courant statorique mesuré i_sa
formula-name-x3 = courant statorique mesuré i_sb
formula-name-xt2 = résidu x̃2 = x2 − x̂2
formula-name-xt3 = résidu x̃3 = x3 − x̂3
formula-name-dxt2 = dérivée nominale de x̃2 : −(a7 + l21)·x̃2 − l22·x̃3
formula-name-dxt3 = dérivée nominale de x̃3 : −l31·x̃2 − (a7 + l32)·x̃3
formula-name-dx4h = dérivée de x̂4 dans l’observateur : −a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4
formula-name-dx5h = dérivée de x̂5 dans l’observateur : −a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5
formula-name-wd = consigne de vitesse ω_d
formula-name-dwd = sa dérivée première
formula-name-ddwd = sa dérivée seconde
formula-name-psi-d = cible de flux pour x̂4² + x̂5²
formula-name-si1 = injection de l’observateur dans x̂1 : l11·x̃2 + l12·x̃3
formula-name-si2 = injection de l’observateur dans x̂2
formula-name-si3 = injection de l’observateur dans x̂3
formula-name-si4 = injection de l’observateur dans x̂4
formula-name-si5 = injection de l’observateur dans x̂5
formula-name-l11 = gain de l’observateur L = K/Ts, ligne 1, colonne 1
formula-name-l12 = gain de l’observateur, ligne 1, colonne 2
formula-name-l21 = gain de l’observateur, ligne 2, colonne 1
formula-name-l22 = gain de l’observateur, ligne 2, colonne 2
formula-name-l31 = gain de l’observateur, ligne 3, colonne 1
formula-name-l32 = gain de l’observateur, ligne 3, colonne 2
formula-name-l41 = gain de l’observateur, ligne 4, colonne 1
formula-name-l42 = gain de l’observateur, ligne 4, colonne 2
formula-name-l51 = gain de l’observateur, ligne 5, colonne 1
formula-name-l52 = gain de l’observateur, ligne 5, colonne 2
formula-name-a1 = μ = 3·np·M/(2·J·Lr) : a1·(x3·x̂4 − x2·x̂5) est le couple divisé par J
formula-name-a2 = T0/J (l’estimée â2 quand l’EKF estime la charge)
formula-name-a3 = Cf/J
formula-name-a5 = α·β, avec α = Rr/Lr et β = M/(σ·Lr)
formula-name-a6 = np·β
formula-name-a7 = γ = Rs/σ + α·β·M
formula-name-a8 = α = Rr/Lr
formula-name-a9 = np
formula-name-a10 = α·M
formula-name-b = 1/σ
formula-name-da2 = dérivée de â2 (son injection) quand l’EKF estime la charge, sinon 0
formula-name-k1 = taux de décroissance de l’erreur de vitesse
formula-name-k2 = taux de décroissance de l’erreur de couple (k2 = a7 + a8 + k2s1)
formula-name-k3 = taux de décroissance de l’erreur de flux
formula-name-k4 = taux de décroissance de l’erreur de dérivée du flux
formula-name-k1s1 = k1 − a3
formula-name-k2s1 = k2 − a7 − a8
formula-name-h2 = borne de |d̃2| de (38)
formula-name-eps2 = ε2 de (38)
formula-name-h4 = borne de |d̃4| de (53)
formula-name-eps4 = ε4 de (53)
formula-name-robust = 1 quand les termes robustes (38) et (53) sont actifs, sinon 0
formula-name-z1 = erreur de vitesse x̂1 − ω_d
formula-name-z3 = erreur de flux x̂4² + x̂5² − ψ_d
formula-name-v1 = commande virtuelle de l’étape 1 (la vôtre si vous l’avez écrite)
formula-name-z2 = erreur de couple a1·(x3·x̂4 − x2·x̂5) − v1
formula-name-v3 = commande virtuelle de l’étape 3 (la vôtre si vous l’avez écrite)
formula-name-z4 = erreur de dérivée du flux 2·a10·(x2·x̂4 + x3·x̂5) − v3

## Les fonctions qu’une loi peut appeler : chacune écrite avec ses arguments, et ce qu’elle donne
## (le nom de la fonction et ses arguments appartiennent au langage : ils restent tels quels)

formula-function-sqrt = sqrt(x) : racine carrée
formula-function-exp = exp(x) : exponentielle
formula-function-ln = ln(x) : logarithme népérien
formula-function-sin = sin(x) : sinus, x en rad
formula-function-cos = cos(x) : cosinus, x en rad
formula-function-tanh = tanh(x) : tangente hyperbolique
formula-function-abs = abs(x) : valeur absolue
formula-function-sign = sign(x) : −1, 0 ou 1
formula-function-atan2 = atan2(y, x) : l’angle de (x, y) (rad)
formula-function-min = min(a, b) : le plus petit
formula-function-max = max(a, b) : le plus grand
formula-function-sat = sat(x, m) : x limité à [−m, m]
