# Les messages du cœur de simulation sur les défis de conception et leur notation : pourquoi un
# lien de défi ou de soumission a été refusé, l’énoncé en toutes lettres, le verdict sur chaque
# critère et la notation d’une classe. La CLI les dit en anglais d’après le fichier anglais ; la
# page, dans la langue du lecteur ; le CSV des notes les contient en anglais. Les clés, champs,
# indicateurs et réglages (c=1, allow.FIELD, need.FIGURE=OP, seeds:A..B, try.FIELD, mean_nis,
# load.torque = 0) sont les mots mêmes du lien : ils restent tels quels. Une saisie citée garde ses
# guillemets.

## Un lien de défi ou de soumission refusé

# $key : la clé du lien (title, vary, try.k1…), $value : le texte qu’elle contient.
challenge-not-percent-encoded = champ '{ $key }' = '{ $value }' : UTF-8 encodé-pourcent non valide
challenge-too-long = le défi fait { $bytes } octets, plus que les { $max } octets ({ $kib } Kio) autorisés
# $names : la liste des noms des défis intégrés.
challenge-unknown = '{ $name }' n’est ni un lien de défi ni un défi intégré ({ $names })
challenge-unsupported-version = champ 'c' = '{ $value }' : version de défi non prise en charge, autorisée : { $version }
# $fields : la liste des clés qu’un lien de défi peut contenir.
challenge-unknown-key = le champ '{ $key }' n’est pas un champ de défi ({ $fields })
challenge-missing = le champ '{ $key }' manque
# $name : le nom du défi intégré.
challenge-builtin-extra = le champ '{ $key }' ne peut pas suivre challenge={ $name } : le lien d’un défi intégré ne contient que challenge=NAME et les parties try.FIELD de l’étudiant
# $stray : les caractères écrits avant c= ; $count : leur nombre.
challenge-stray = le lien commence par { $count ->
        [one] le caractère parasite
       *[other] les caractères parasites
    } '{ $stray }' avant son c={ $version } : { $count ->
        [one] supprimez-le
       *[other] supprimez-les
    }
challenge-version-missing = le champ 'c' manque (un défi commence par c={ $version })
challenge-title-too-long = le champ 'title' compte { $chars } caractères, plus que les { $max } autorisés
# $error : pourquoi le scénario de base a été refusé (un message scenario-*).
challenge-bad-base = champ 'base' : { $error }
challenge-no-criteria = aucun critère : ajoutez au moins un need.FIGURE=OP
challenge-too-many-criteria = { $count } critères, plus que les { $max } autorisés
challenge-vary-unused = champ 'vary' : aucun critère n’utilise les variantes (nommez dans robust= l’indicateur de chaque critère qui doit tenir sur elles)
challenge-robust-without-vary = champ 'robust' : il n’y a pas de variantes (ajoutez vary=)
# $key : allow.FIELD ; $field : le champ de scénario qu’il nomme.
challenge-allow-unknown-field = champ '{ $key }' : '{ $field }' n’est pas un champ de scénario
challenge-allow-formula = champ '{ $key }' = '{ $value }' : la loi d’une étape s’autorise sous la forme allow.{ $field }=formula
challenge-allow-range = champ '{ $key }' = '{ $value }' : LO..HI attendu, deux nombres avec LO ≤ HI
# $error : pourquoi une extrémité de la plage n’est pas une valeur du champ (un message scenario-*).
challenge-allow-refused = champ '{ $key }' = '{ $value }' : { $error }
# $options : la liste des noms du champ, séparés par |.
challenge-allow-choice = champ '{ $key }' = '{ $value }' : des noms distincts parmi { $options } sont attendus, séparés par |
# $key : need.FIGURE ; $figures : la liste des indicateurs qu’un critère peut nommer.
challenge-need-unknown-figure = champ '{ $key }' : '{ $figure }' n’est pas un indicateur ({ $figures })
challenge-need-band = champ '{ $key }' = 'band' : seul mean_nis a une bande
challenge-need-op = champ '{ $key }' = '{ $value }' : max:B, min:B, abs:B ou band attendu
challenge-need-no-load-step = champ '{ $key }' : la base n’a pas d’échelon de charge (load.torque = 0, ou un tableau de charge à la place)
challenge-vary-seeds = champ 'vary' = '{ $value }' : seeds:A..B attendu, des nombres entiers avec A ≤ B ≤ { $max_seed } et au plus { $max } graines
challenge-vary-too-many = champ 'vary' : { $count } variantes, plus que les { $max } autorisées
# $number compte les variantes à partir de 1 ; $error : ce qui ne va pas (un message scenario-*).
challenge-vary-variant-refused = champ 'vary', variante { $number } : { $error }
challenge-vary-variant-empty = champ 'vary' : la variante { $number } est vide
# $overrides : les réglages de la variante (seed=2) ; $error : pourquoi ils ne s’appliquent pas.
challenge-variant-refused = variante '{ $overrides }' : { $error }
# $value : la liste robust=, $figure : le nom qu’elle contient qui n’est pas celui d’un critère.
challenge-robust-unknown = champ 'robust' = '{ $value }' : '{ $figure }' n’est l’indicateur d’aucun critère (ou est nommé deux fois)
challenge-is-submission = champ 'try.{ $key }' : c’est une soumission, pas un défi (notez-la au regard de son défi)
challenge-another = la soumission appartient à un autre défi (le texte de son défi diffère)
challenge-try-not-allowed = le champ '{ $field }' n’est pas autorisé
challenge-try-not-number = champ 'try.{ $field }' = '{ $value }' : pas un nombre
# $setting : le réglage de l’étudiant (k1=6000), $range : la plage autorisée (300..5000).
challenge-try-outside = { $setting } est hors de { $range }
# $options : la liste des noms autorisés, séparés par |.
challenge-try-not-option = { $setting } ne fait pas partie de { $options }
challenge-compose-range-and-options = champ '{ $key }' : donnez LO et HI (une plage) ou des options (des choix), pas les deux
challenge-judge-runs = le défi compte { $runs ->
        [one] { $runs } simulation
       *[other] { $runs } simulations
    } (la nominale et { $variants ->
        [one] { $variants } variante
       *[other] { $variants } variantes
    }), { $measured ->
        [one] { $measured } mesurée
       *[other] { $measured } mesurées
    }

## L’énoncé en toutes lettres

challenge-untitled = Défi de conception
# Le titre du défi, tel que l’auteur l’a écrit.
challenge-title = { $title }
# $base : la chaîne du scénario.
challenge-brief-start = Partez du scénario { $base }
challenge-brief-nothing-allowed = Rien ne peut être modifié : la base est jugée telle quelle.
challenge-brief-allowed = Vous ne pouvez modifier que :
# Un champ que l’étudiant peut modifier : $field son nom (complété en colonne), $range ce qu’il
# peut valoir (un message challenge-brief-range, -one-of ou -formula), $now la valeur de la base,
# $doc le champ en toutes lettres.
challenge-brief-allow = { $field } { $range } (actuellement { $now }) — { $doc }
# $hi porte son unité, s’il en a une.
challenge-brief-range = de { $lo } à { $hi }
# $options : la liste des noms.
challenge-brief-one-of = l’une des valeurs { $options }
challenge-brief-formula = une formule de votre choix
challenge-brief-formula-unit = une formule de votre choix, en { $unit }
challenge-brief-needs = Votre conception doit satisfaire :
# Un critère : $number les compte à partir de 1, $label est l’indicateur en toutes lettres, $figure
# son nom, $bound un message challenge-brief-at-most, -at-least, -within ou -band ; $settled vaut
# yes pour une valeur finale, qui doit être établie ; $robust vaut yes s’il doit aussi tenir sur
# chaque variante.
challenge-brief-need = { $number }. { $label } ({ $figure }) : { $bound }{ $settled ->
        [yes] , et établie à la fin de la simulation
       *[no] {""}
    }{ $robust ->
        [yes] {" "}— sur la simulation nominale et sur chaque variante
       *[no] {""}
    }
# $bound porte son unité, s’il en a une.
challenge-brief-at-most = au plus { $bound }
challenge-brief-at-least = au moins { $bound }
challenge-brief-within = dans l’intervalle ±{ $bound }
challenge-brief-band = dans la bande à 95 % d’un filtre cohérent (de mean_nis_low à mean_nis_high)
# $first et $last : la première et la dernière graine de bruit (seed=2…).
challenge-brief-variants-seeds = Variantes (appliquées par-dessus vos réglages ; la pire simulation compte) : graines de bruit { $first } à { $last }
# $overrides : les réglages de chaque variante, séparés par des points-virgules.
challenge-brief-variants = Variantes (appliquées par-dessus vos réglages ; la pire simulation compte) : { $overrides }
challenge-brief-load-recovery = Temps de rétablissement après l’échelon de charge : le temps écoulé entre l’échelon de charge (t = { $time } s) et l’instant à partir duquel |ω − ω_d| reste dans max(1 % de |ω_d| à l’échelon, 0,5 rad/s) jusqu’à la fin de la simulation (ici { $band } rad/s à ω_d = { $speed } rad/s) ; non rétabli si l’écart en sort encore à la fin.
challenge-brief-settled = Une valeur finale ne compte que si elle est établie : une valeur qui évolue encore sur le dernier dixième de la simulation échoue.
# Un nombre et son unité : « 0,004 s ».
challenge-quantity = { $value } { $unit }

## La borne d’un critère, et pourquoi il échoue

# $bound porte son unité, s’il en a une : « ≤ 0,004 s ».
challenge-bound-max = ≤ { $bound }
challenge-bound-min = ≥ { $bound }
challenge-bound-abs = |·| ≤ { $bound }
challenge-bound-band = dans sa bande à 95 %
# $failure : pourquoi la simulation a échoué.
challenge-run-unfinished = la simulation n’est pas allée à son terme
challenge-reason-run-failed = échec de la simulation : { $failure }
# $cause : pourquoi l’indicateur n’est pas un nombre.
challenge-reason-not-finite = { $cause }
challenge-reason-before-load-step = non mesuré : la simulation s’arrête avant l’échelon de charge
challenge-reason-not-measured = non mesuré sur cette simulation (par exemple un échelon qui ne s’établit jamais à 2 % près)
challenge-reason-no-band = non mesuré : pas de bande de NIS sur cette simulation
challenge-reason-above-bound = au-dessus de la borne
challenge-reason-below-bound = en dessous de la borne
challenge-reason-beyond-bound = au-delà de la borne
challenge-reason-below-band = sous la bande
challenge-reason-above-band = au-dessus de la bande
challenge-reason-not-recovered = non rétabli à la fin de la simulation
challenge-reason-still-changing = évolue encore

## La notation d’une classe : l’état de chaque soumission (aussi dans le CSV des notes) et le fichier de la classe

grade-row-ok = ok
# $reason : pourquoi le lien n’est pas une soumission bien formée.
grade-row-malformed = mal formée : { $reason }
# $reason nomme le champ réglé par l’étudiant qui n’est pas autorisé, ou hors de sa plage.
grade-row-refused = refusée : { $reason }
grade-row-another = autre défi
# $reason : pourquoi une simulation a échoué.
grade-row-run-failed = échec de la simulation : { $reason }
grade-internal-error = erreur interne
# $encoding : le nom de l’encodage dans lequel le fichier a été lu (UTF-8, windows-1252…).
grade-line-undecoded = la ligne { $line } n’est pas du { $encoding } valide
grade-line-unclosed = ligne { $line } : un champ entre guillemets n’est pas refermé avant la fin du fichier
grade-line-fields = la ligne { $line } compte { $fields ->
        [one] { $fields } champ
       *[other] { $fields } champs
    }, contre { $header } pour l’en-tête
grade-no-link = aucun lien
# $error : pourquoi le défi a été refusé.
grade-challenge-refused = défi : { $error }
grade-file-not-text = le fichier n’est pas du texte (il contient des octets NUL : un tableur ou un document ?) ; enregistrez-le comme fichier texte de liens, un par ligne, ou en CSV
grade-file-utf16 = le fichier est en UTF-16 sans indicateur d’ordre des octets ; enregistrez-le en UTF-8
grade-file-header-undecoded = la ligne { $line }, l’en-tête CSV, n’est pas du { $encoding } valide
# $columns : la liste des en-têtes de colonne du fichier, chacun entre guillemets.
grade-file-no-link-column = aucune colonne de liens dans cet export CSV (ses colonnes : { $columns }) ; intitulez la colonne des liens 'link'
grade-file-links-everywhere = les colonnes { $columns } contiennent toutes des liens ; intitulez 'link' celle à noter
grade-file-link-headers = les colonnes { $columns } sont toutes intitulées comme colonnes de liens ; n’en gardez qu’une

## Reprendre une notation interrompue (imlab grade --resume) : pourquoi son résultat antérieur est refusé

grade-resume-not-utf8 = le fichier n’est pas du texte UTF-8 : ce ne sont donc pas les notes de cette classe
# $header : la ligne d’en-tête CSV qu’écrit cette notation.
grade-resume-header = sa première ligne n’est pas l’en-tête de cette notation '{ $header }' : le fichier contient les notes d’un autre défi ou d’un autre fichier de classe
grade-resume-too-many-rows = le fichier contient plus de lignes que le fichier de classe n’a de soumissions ({ $rows })
grade-resume-row = sa ligne { $row } ne correspond pas à la ligne { $line } ('{ $link }') du fichier de classe : le fichier contient les notes d’un autre fichier de classe
# $what : un des messages grade-kept-*.
grade-kept-differs = sa ligne { $row } (ligne { $line } du fichier de classe) diffère de ce que donne une nouvelle notation : { $what } ; elle a été modifiée après sa notation, ou notée par une autre version d’imlab
# $column : le nom de la colonne CSV (status, settling_time_pass…).
grade-kept-cell = sa colonne { $column } vaut '{ $found }', et non '{ $expected }'
grade-kept-extra = elle contient '{ $extra }' après sa dernière colonne
grade-kept-short = il lui manque ses colonnes à partir de { $column }
