# The core's refusals of a formula, and why a law's distance from its designed dynamics is not a
# number: said as a link is read or a run ends, with the page's first messages.
# $reason : un des messages formula-* ci-dessous ; $at compte les caractères à partir de 1.
formula-at = au caractère { $at } : { $reason }
# $written : le nombre tel que saisi.
formula-not-a-number = '{ $written }' n’est pas un nombre
formula-number-too-large = '{ $written }' est trop grand pour un nombre
# $char : le caractère saisi.
formula-not-in-language = '{ $char }' ne fait pas partie du langage (+ − * / ^, parenthèses, noms, nombres)
formula-division-by-zero = division par zéro
formula-nests-too-deep = la formule s’imbrique ici sur plus de { $max } niveaux
formula-ends-early = la formule s’arrête là où un nombre, un nom ou '(' est attendu
formula-never-closed = cette '(' n’est jamais refermée
formula-expected-close = ')' ou un opérateur attendu ici
# $op : l’opérateur saisi (* / ^ ) ou ,) ; un produit écrit · ou × est donné comme *.
formula-misplaced-operator = '{ $op }' là où un nombre, un nom ou '(' est attendu
# $name : le nom saisi ; $functions : la liste des fonctions.
formula-no-function = pas de fonction '{ $name }' : les fonctions sont { $functions }
# $name : le nom d’une fonction (« dans sqrt( ) »).
formula-expected-argument-end = ',' ou ')' attendu dans { $name }( )
# $arity : le nombre d’arguments de la fonction ; $given : le nombre donné.
formula-arguments = { $name } prend { $arity } { $arity ->
        [one] argument
       *[other] arguments
    }, et non { $given }
# $from : l’étape dont la loi fournit le nom.
formula-later-name = '{ $name }' n’est pas connu à l’étape { $step } : il vient de la loi de l’étape { $from }
formula-is-function = '{ $name }' est une fonction : écrivez { $name }( )
# $name : x1, la vitesse réelle.
formula-true-speed = '{ $name }' est la vitesse réelle, dont ne dispose pas un correcteur sans capteur : écrivez son estimée x1h
# $name : x4 ou x5, un flux rotorique réel.
formula-true-flux = '{ $name }' est un flux rotorique réel, qu’aucun variateur ne mesure : écrivez son estimée x4h ou x5h
# $name : xt1, xt4 ou xt5.
formula-unmeasured-error = '{ $name }' est l’erreur d’estimation d’un état non mesuré, qu’un correcteur sans capteur ne peut pas connaître : l’article laisse ces termes dans d̃2 et d̃4, contre lesquels le terme robuste (robust·h²/(4ε)·z) est conçu
formula-unknown-name = nom inconnu '{ $name }' (voir la liste des noms)
formula-too-long = la formule compte { $length } caractères, plus que les { $max } autorisés
formula-empty = la formule est vide
formula-unopened = cette ')' n’est précédée d’aucune '('
formula-expected-operator = opérateur attendu ici (un produit s’écrit avec *)
formula-too-many-operations = la formule demande { $operations } opérations, plus que les { $max } autorisées
formula-too-deep = la formule imbrique ses valeurs sur { $depth } niveaux, plus que les { $max } autorisés : écrivez-la avec moins de parenthèses imbriquées
# $error : un message formula-*, avec sa position.
law-refused = law.v{ $step } : { $error }
law-no-such-step = étape { $step } : les étapes vont de 1 à 4
law-none = le scénario n’a pas de loi propre : donnez law.v1, law.v2, law.v3 ou law.v4
law-no-own-law = l’étape n’a pas de loi propre
law-not-designed-one = la loi ne donne pas sa dynamique voulue
# $failed lois propres du scénario sur $laws.
law-not-designed-some = { $failed ->
        [one] { $failed } loi sur { $laws } ne donne pas sa dynamique voulue
       *[other] { $failed } lois sur { $laws } ne donnent pas leur dynamique voulue
    }
law-never-runs = votre { $before } ne donne de valeur finie en aucun des { $draws } états tirés, si bien que l’étape { $step } ne s’exécute jamais
law-no-share = votre { $output } ({ $unit }) diffère de la { $output } qui donne la dynamique voulue là où la loi de l’article est quasi nulle, d’un écart relatif qui n’est pas fini
# $count des $draws états tirés ; $reads vaut none si la loi ne lit aucun signal, sinon $names
# liste les noms lus avec leur valeur (law-named-value).
law-differs-infinitely = votre { $output } ({ $unit }) diffère infiniment de la { $output } qui donne la dynamique voulue en { $count } des { $draws } états tirés{ $reads ->
        [none] , sans lire aucun signal
       *[some] , par exemple en { $names }
    }
# Comme law-differs-infinitely ; $value : ce que donne la loi (inf, -inf ou NaN).
law-not-finite = votre { $output } ({ $unit }) n’est pas un nombre fini en { $count } des { $draws } états tirés : elle donne { $value }{ $reads ->
        [none] , sans lire aucun signal
       *[some] {" "}en { $names }
    }
# Un nom lu par une loi et sa valeur : « z1 = 0,25 ».
law-named-value = { $name } = { $value }
law-paper-zero = la loi de l’article est restée nulle sur toute la simulation, la vôtre non
