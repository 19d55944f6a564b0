# Les mots du cœur de simulation sur une simulation : le sens de chaque réglage, ce que montre
# chaque préréglage, les indicateurs d’une simulation et la partie qu’ils couvrent, les
# avertissements sans lesquels ils ne doivent pas être lus, la fin du transitoire de démarrage, et
# pourquoi une simulation s’est arrêtée. La CLI les dit en anglais d’après le fichier anglais
# (`imlab describe`, `imlab presets`, `imlab metrics`) ; la page, dans la langue du lecteur. Les
# clés et noms de champs (k1, law.v1, ekf.q), les valeurs d’un champ (euler, rk4, box), les
# symboles (ω_d, φa², Rs, |i_s|), les unités, les formules et les numéros d’équation et de figure
# de l’article ((38), Fig 2) restent tels quels.

## Un instant

# Un temps en millisecondes ou en secondes, avec au plus 4 chiffres significatifs.
time-ms = { $ms } ms
time-s = { $s } s

## Le sens de chaque réglage (sa clé, son unité et sa plage sont celles du codec)

# (0/1) marque un interrupteur : 0 désactivé, 1 activé.

field-design = conception : paper (article, valeurs réglées) ou derived (données du moteur)
field-ref = type de consigne de vitesse
field-ref-value = vitesse constante
field-sine-amp = amplitude du sinus
field-sine-freq = fréquence du sinus
field-sine-offset = constante ajoutée au sinus
field-step-size = amplitude de l’échelon
field-step-time = instant de l’échelon
field-step-wn = pulsation propre ωn du filtre de l’échelon
field-ramp-start = début de la rampe
field-ramp-level = niveau du palier de la rampe
field-ramp-slope = pente de la rampe, en valeur absolue
field-ramp-hold = durée du palier de la rampe
field-rev-start = début de la montée avant l’inversion
field-rev-level = vitesse inversée, de +level à −level
field-rev-slope = pente de l’inversion, en valeur absolue
field-rev-hold = durée à +level avant l’inversion
field-ref-table = consigne donnée par un tableau de points t:ω_d, en ligne droite entre eux
field-psi_d = cible de flux pour φa² + φb²
field-fw = défluxage au-delà de la vitesse de base (0/1)
field-fw-base = vitesse de base du défluxage
field-k1 = taux de décroissance de l’erreur de vitesse k1
field-k2 = taux de décroissance de l’erreur de couple k2 = a7 + a8 + k2s1
field-k3 = taux de décroissance de l’erreur de flux k3
field-k4 = taux de décroissance de l’erreur de dérivée du flux k4
field-robust = appliquer les termes robustes (38) et (53) (0/1)
field-eps2 = ε2 de (38) : la borne de z2·(v2s2 + d̃2)
field-h2 = h2 de (38) : borne de |d̃2|
field-eps4 = ε4 de (53) : la borne de z4·(v4s2 + d̃4)
field-h4 = h4 de (53) : borne de |d̃4|
field-law-v1 = votre étape 1 : la commande virtuelle v1 (vide : la loi (26) de l’article)
field-law-v2 = votre étape 2 : v2 (vide : la loi (34) de l’article)
field-law-v3 = votre étape 3 : la commande virtuelle v3 (vide : la loi (45) de l’article)
field-law-v4 = votre étape 4 : v4 (vide : la loi (49) de l’article)
# backstepping et ifoc sont les valeurs du champ : elles restent telles quelles.
field-controller = backstepping (article) ou ifoc (FOC classique sans capteur, pour comparaison)
field-ifoc-bw_i = bande passante de la boucle de courant de l’IFOC
field-ifoc-bw_w = bande passante de la boucle de vitesse de l’IFOC
field-ifoc-bw_mras = bande passante de l’estimateur de vitesse MRAS de l’IFOC
field-ifoc-i_max = limite du courant d’axe q de l’IFOC
field-ifoc-ff = anticipation de couple de l’IFOC J·ω̇_d + T0 + Cf·ω_d (0/1)
# euler et rk4 sont les valeurs du champ : elles restent telles quelles.
field-ekf = prédicteur de l’EKF : euler (article) ou rk4
field-ekf-q = bruit de processus Q = q·Ts·I, un même nombre pour tous les états : A²/s pour les courants, (rad/s)²/s pour ω, Wb²/s pour les flux
field-ekf-q_speed = bruit de processus ajouté au seul état de vitesse, Q_ωω = (q + q_speed)·Ts
field-ekf-r_std = bruit de courant supposé, R = r_std²·I
field-ekf-load = estimer la charge a2 = T_L0/J comme état de l’EKF (0/1)
field-ekf-q_load = intensité de la marche aléatoire du couple de charge
field-ekf-load_std = écart type initial de l’estimée de la charge
field-ekf-rr = estimer la résistance rotorique R_r comme état de l’EKF (0/1)
field-ekf-q_rr = intensité de la marche aléatoire de la résistance rotorique
field-ekf-rr_std = écart type initial de l’estimée de R_r
field-init_err = erreur d’estimation relative initiale
field-start = état initial : paper (2 A, 2 A, 0,5 Wb, 0,5 Wb) ou magnetized (magnétisé à la cible de flux)
field-perfect = observateur parfait : le correcteur reçoit l’état réel (0/1)
field-noise = écart type du bruit de mesure des courants
field-seed = graine du bruit
# Les paramètres du moteur simulé (plant) ; ceux du modèle, que supposent le correcteur et
# l’observateur, se lisent de même.
field-motor = moteur simulé et moteur du modèle à la fois, avec son courant nominal
field-plant-rs = résistance statorique Rs
field-plant-rr = résistance rotorique Rr
field-plant-m = inductance mutuelle M
field-plant-ls = inductance statorique Ls
field-plant-lr = inductance rotorique Lr
field-plant-j = inertie du rotor J
field-plant-np = nombre de paires de pôles np
field-plant-t0 = couple de charge constant T0
field-plant-cf = frottement visqueux Cf
field-model-rs = { field-plant-rs }
field-model-rr = { field-plant-rr }
field-model-m = { field-plant-m }
field-model-ls = { field-plant-ls }
field-model-lr = { field-plant-lr }
field-model-j = { field-plant-j }
field-model-np = { field-plant-np }
field-model-t0 = { field-plant-t0 }
field-model-cf = { field-plant-cf }
field-load-time = instant de l’échelon de charge inconnu
field-load-torque = amplitude de l’échelon de charge inconnu
field-load-table = couple de charge inconnu donné par un tableau de points t:torque, en ligne droite entre eux (au lieu de l’échelon)
field-vmax = limite de tension par composante
field-duration = durée simulée
field-ts = période d’échantillonnage Ts
field-substeps = sous-pas RK4 du moteur par échantillon
field-i_rated = courant nominal : amplitude |i_s| du courant de phase nominal
field-rated-v = tension nominale, efficace entre phases
field-rated-f = fréquence nominale
field-delay = retard de calcul : u_k appliquée un échantillon plus tard (0/1)
field-delay-comp = compensation du retard : commande calculée sur la prédiction à un pas x̂(k+1|k) (0/1)
# box, circle et hex sont les valeurs du champ : elles restent telles quelles.
field-vlimit = limite de tension : box (±vmax par composante, l’article), circle (|u| ≤ vdc/√3) ou hex (onduleur à deux niveaux)
field-vdc = tension du bus continu des limites circle et hex et de la PWM
field-pwm = onduleur à deux niveaux, PWM symétrique à la fréquence d’échantillonnage (0/1 ; vlimit circle ou hex)

## Ce que montre chaque préréglage (preset-NAME : le préréglage NAME)

# Le nom d’un préréglage dans une description (sine200, load-step, rr-mismatch) est celui du lien :
# il reste tel quel.

preset-sine200 = Fig 2 de l’article : poursuite de 0,5 sin(2π·200 t) rad/s avec l’EKF ; le courant dépasse en crête le courant nominal du moteur
preset-step = Fig 3 de l’article : échelon de 0 → 0,5 rad/s à 50 ms, à travers un filtre à amortissement critique de 200 Hz
preset-ramp = Fig 4 de l’article : trapèze jusqu’à 100 rad/s à ±400 rad/s², palier, puis retour
preset-sine200-1rad = 1 rad/s à 200 Hz : sature la limite de 400 V, et son erreur de poursuite dépasse le triple de celle de sine200
preset-sine200-rk4 = Fig 2 avec un prédicteur RK4 dans l’EKF au lieu de l’Euler de l’article
preset-rr-mismatch = Maintien à 50 rad/s avec la résistance rotorique du moteur 10 % au-dessus de celle du modèle : la vitesse réelle se remet du démarrage sur plusieurs secondes et s’établit au-dessus de la consigne (simulez 6 s pour en voir la fin)
preset-load-step = Maintien à 50 rad/s ; un échelon de charge inconnu de 2 N m à 0,15 s, que l’EKF à 5 états ne peut pas voir
preset-decay = Observateur parfait, sans bruit, ω_d ≡ 0 : les erreurs décroissent au taux voulu de 1200/s, puis s’arrêtent à un plancher qui diminue avec la période d’échantillonnage
preset-ifoc-step = Base de comparaison classique : IFOC sans capteur avec un MRAS, échelon jusqu’à 40 rad/s (le MRAS est aveugle près de la vitesse nulle)
preset-load-step-est = load-step avec la charge a2 comme état de l’EKF (prédicteur RK4) : la vitesse tient pendant l’échelon inconnu avec un modèle exact, mais pas avec la R_r du moteur 3 % en dessous de celle du modèle
preset-rr-mismatch-est = rr-mismatch (écart de R_r) avec R_r comme état de l’EKF (prédicteur RK4) : pas de transitoire lent, et R̂_r reste proche de la valeur du moteur
preset-sine200-drive = Les 200 Hz résistent-ils à un vrai variateur ? sine200 avec un retard de calcul d’un échantillon, l’hexagone de l’onduleur à 540 V et la PWM
preset-high-gain = Gains de 3000/s (2,5× l’article) : les erreurs de prédiction de l’EKF d’Euler, à travers les gains, saturent la limite de 400 V

## Les indicateurs d’une simulation (`imlab metrics` les nomme par la partie qui suit figure-)

figure-transient_end = fin du transitoire de démarrage
figure-tracking_rms = RMS de ω − ω_d
figure-tracking_peak = |ω − ω_d| crête
figure-settling_time = temps de réponse à 2 % de ω après l’échelon
figure-saturated_share = part des échantillons à la limite de tension
figure-mean_nis = NIS moyen
figure-mean_nis_low = NIS moyen, bas de la bande à 95 % d’un filtre cohérent
figure-mean_nis_high = NIS moyen, haut de la bande à 95 % d’un filtre cohérent
figure-current_peak = courant statorique crête |i_s|
figure-current_rms = courant statorique RMS |i_s|
figure-current_rated = courant nominal |i_s| (i_rated)
figure-ripple_peak = ondulation crête du courant PWM
figure-ripple_rms = RMS sur les périodes de l’ondulation crête du courant PWM
figure-flux_error_final = erreur de flux finale |φ_r| − √ψ_d
figure-speed_error_final = erreur de vitesse finale ω − ω_d
figure-speed_estimate_error_final = erreur finale de l’estimée de vitesse ω − ω̂
figure-law_residual = plus grand résidu de la dynamique voulue de vos lois, sur la simulation et aux états tirés du verdict, rapporté à la loi de l’article
# Pas parmi les indicateurs de la simulation : un défi peut le nommer.
figure-load_recovery_time = temps de rétablissement après l’échelon de charge

## La partie de la simulation que couvre un indicateur

# $time : un temps (time-ms ou time-s), la fin du transitoire de démarrage.
window-after-transient = t ≥ { $time }
window-start-up = démarrage, t < { $time }
# $time : l’instant de l’échelon de la consigne.
window-from-step = depuis l’échelon à { $time }
window-rating = le courant nominal du moteur
# $time : l’instant du dernier échantillon.
window-last-sample = dernier échantillon, t = { $time }
window-law-residual = toute la simulation et les états tirés du verdict

## Un indicateur que la simulation n’avait pas atteint à sa fin, dit à la place de sa valeur

# $time : l’instant du dernier échantillon.
unreached-not-settled = non établi à la fin de la simulation (t = { $time })

## Ce sans quoi les indicateurs d’une simulation ne doivent pas être lus

# $speed : ω − ω_d à la fin, $estimate : ω̂ − ω, $flux : le module du flux, $target : sa cible √ψ_d.
warning-runaway = La simulation a divergé : à sa fin, la vitesse réelle est à { $speed } rad/s de la consigne, l’estimée de vitesse à { $estimate } rad/s de la vitesse réelle, et le flux vaut { $flux } Wb pour une cible de { $target } Wb. Le correcteur régule les estimées de l’EKF ; le théorème 4.6 ne borne la boucle fermée que tant que les erreurs d’estimation restent bornées, et quand elles ne le sont pas (une erreur au démarrage retenue par la seule limite de tension, un modèle faux à basse vitesse), rien ne borne le moteur.
# $low et $high : les bornes de la bande.
warning-inconsistent-above = L’EKF est incohérent sur cette simulation : son NIS moyen vaut { $nis }, très au-dessus de la bande à 95 % { $low }–{ $high } d’un filtre dont le modèle est juste. Ses estimées, et la vitesse sur laquelle agit le correcteur, peuvent être loin de la vérité, si étroites que paraissent leurs bandes.
warning-inconsistent-below = L’EKF est incohérent sur cette simulation : son NIS moyen vaut { $nis }, très en dessous de la bande à 95 % { $low }–{ $high } d’un filtre dont le modèle est juste. Il suppose plus de bruit qu’il n’y en a : il suit donc les mesures plus lentement qu’il ne le pourrait.
# $figure : le nom de l’indicateur (law_residual) ; $cause : pourquoi ce n’est pas un nombre.
warning-not-following = La vitesse ne suit pas sa consigne : de t = { $since } à la fin de la simulation, ω − ω_d reste hors de ±({ $share } % de |ω_d| + { $margin } rad/s), et finit à { $error } rad/s pour ω_d = { $reference } rad/s.
warning-not-following-window = La vitesse ne suit pas sa consigne : sur toute la fenêtre des indicateurs, de t = { $since } à la fin de la simulation, ω − ω_d reste hors de ±({ $share } % de |ω_d| + { $margin } rad/s), et finit à { $error } rad/s pour ω_d = { $reference } rad/s.
warning-not-finite = { $figure } n’est pas un nombre fini : { $cause }.

## Où finit le transitoire de démarrage, et pourquoi à cet endroit

transient-nothing-recorded = rien n’a encore été enregistré
# À la place d’un temps : le critère n’a jamais été rempli dans la première moitié.
transient-never = jamais dans la première moitié (non utilisé)
# $k : le plus petit des gains k1..k4 (1/s) ; $time : le démarrage du correcteur.
transient-backstepping = 5 constantes de temps du taux d’erreur voulu le plus lent (1/{ $k } s) = { $time }
# $bw : la bande passante ifoc.bw_i (Hz) ; $time : le démarrage du correcteur.
transient-ifoc = 5 constantes de temps des boucles de courant de l’IFOC (1/(2π·{ $bw } Hz)) = { $time }
# $controller : transient-backstepping ou transient-ifoc ; $observer, $estimates, $flux et $speed
# sont des temps, ou transient-never ; $end vaut event si le transitoire a été coupé au premier
# événement du scénario (l’échelon ou l’échelon de charge), half s’il a été limité à la moitié de
# la simulation, sinon none ; $at : l’instant de cet événement ou de la mi-simulation.
transient-reason = { $controller }, comptées à partir du démarrage de l’observateur — covariance d’innovation de l’EKF établie (bande 2σ à moins de 10 % de sa valeur finale) : { $observer } ; estimées de l’EKF convergées (NIS moyen sur 2 ms à moins de deux fois son niveau de la seconde moitié, pendant 5 ms) : { $estimates } ; estimée de flux à moins de 1,5 fois son erreur RMS ultérieure (pendant 5 ms) : { $flux } ; estimée de vitesse à moins de deux fois son erreur RMS ultérieure (fenêtres de 5 ms, pendant 5 ms) : { $speed }{ $end ->
        [event] ; coupé au premier événement du scénario, à { $at }
        [half] ; limité à la moitié de la simulation enregistrée ({ $at })
       *[none] {""}
    }

## Pourquoi une simulation s’est arrêtée

# $t : l’instant de l’échantillon (s) ; $signal : l’état sorti de ses bornes (omega, i_sa, phi_a…) ;
# $value : sa valeur, en notation scientifique (1.2e5, NaN).
sim-diverged = divergence à t = { $t } s : { $signal } = { $value } est sorti de ses bornes
# $column : une colonne du CSV de la simulation ; $value : inf, -inf ou NaN.
sim-not-finite = arrêt à t = { $t } s : la colonne '{ $column }' enregistrerait { $value }, qui n’est pas un nombre fini
# $error : un message control-*.
sim-control = le correcteur a échoué à t = { $t } s : { $error }
# $formula : la loi de l’étudiant telle que saisie ; $value : inf, -inf ou NaN ; $reading :
# sim-law-reads-nothing ou sim-law-reads.
sim-law = votre law.v{ $step } = { $formula } a donné { $value } à t = { $t } s, { $reading }
sim-law-reads-nothing = sans lire aucun signal
# $signals : les noms lus par la loi avec leur valeur (x1h = 52,3, z1 = 0,01).
sim-law-reads = en lisant { $signals }
# $flux et $min en notation scientifique (Wb²).
control-singular = la matrice de découplage (55) est singulière : le flux estimé x̂4² + x̂5² = { $flux } Wb² est inférieur à { $min } Wb²
control-law = la loi de l’étape { $step } a donné { $value }, qui n’est pas un nombre fini
pin-room-full = au plus { $max } simulations peuvent être épinglées ; désépinglez-en une d’abord
pin-legend-same = même scénario
overlay-ts-differs = la simulation épinglée { $scenario } échantillonne à Ts = { $pinned } s, l’actuelle à { $current } s : les superpositions demandent le même Ts
