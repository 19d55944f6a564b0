# The core's refusals of a formula, and why a law's distance from its designed dynamics is not a
# number: said as a link is read or a run ends, with the page's first messages.
# $reason is one of the formula-* messages below; $at counts the formula's characters from 1.
formula-at = bei Zeichen { $at }: { $reason }
# $written is the number as typed.
formula-not-a-number = '{ $written }' ist keine Zahl
formula-number-too-large = '{ $written }' ist als Zahl zu groß
# $char is the character typed.
formula-not-in-language = '{ $char }' gehört nicht zur Formelsprache (+ − * / ^, Klammern, Namen, Zahlen)
formula-division-by-zero = Division durch null
formula-nests-too-deep = Die Formel ist hier tiefer als { $max } Ebenen verschachtelt
formula-ends-early = Die Formel endet, wo eine Zahl, ein Name oder '(' erwartet wird
formula-never-closed = Diese '(' wird nie geschlossen
formula-expected-close = Hier wird ')' oder ein Operator erwartet
# $op is the operator typed (* / ^ ) or ,), a product written · or × given as *.
formula-misplaced-operator = '{ $op }', wo eine Zahl, ein Name oder '(' erwartet wird
# $name is the name typed; $functions lists the functions' names.
formula-no-function = keine Funktion '{ $name }': Die Funktionen sind { $functions }
# $name is a function's name: "in sqrt( )".
formula-expected-argument-end = In { $name }( ) wird ',' oder ')' erwartet
# $arity is how many arguments the function takes, $given how many it was given.
formula-arguments = { $name } erwartet { $arity } { $arity ->
        [one] Argument
       *[other] Argumente
    }, nicht { $given }
# $from is the step whose law gives the name.
formula-later-name = '{ $name }' ist in Schritt { $step } nicht bekannt: Es stammt aus dem Regelgesetz von Schritt { $from }
formula-is-function = '{ $name }' ist eine Funktion: Schreiben Sie { $name }( )
# $name is x1, the true speed.
formula-true-speed = '{ $name }' ist die wahre Drehzahl, die ein drehgeberloser Regler nicht kennt: Schreiben Sie ihren Schätzwert x1h
# $name is x4 or x5, a true rotor flux.
formula-true-flux = '{ $name }' ist ein wahrer Rotorfluss, den kein Antrieb misst: Schreiben Sie seinen Schätzwert x4h oder x5h
# $name is xt1, xt4 or xt5.
formula-unmeasured-error = '{ $name }' ist der Schätzfehler eines nicht gemessenen Zustands, den ein drehgeberloser Regler nicht kennen kann: Der Artikel belässt solche Terme in d̃2 und d̃4, gegen die der robuste Term (robust·h²/(4ε)·z) entworfen ist
formula-unknown-name = unbekannter Name '{ $name }' (siehe die Liste der Namen)
formula-too-long = Die Formel hat { $length } Zeichen, mehr als die zulässigen { $max }
formula-empty = Die Formel ist leer
formula-unopened = Vor dieser ')' steht keine '('
formula-expected-operator = Hier wird ein Operator erwartet (ein Produkt wird mit * geschrieben)
formula-too-many-operations = Die Formel braucht { $operations } Operationen, mehr als die zulässigen { $max }
formula-too-deep = Die Formel ist { $depth } Ebenen tief verschachtelt, mehr als die zulässigen { $max }: Schreiben Sie sie mit weniger verschachtelten Klammern
# $error is a formula-* message, with its place.
law-refused = law.v{ $step }: { $error }
law-no-such-step = Schritt { $step }: Die Schritte sind 1 bis 4
law-none = Das Szenario hat kein eigenes Regelgesetz: Geben Sie law.v1, law.v2, law.v3 oder law.v4 an
law-no-own-law = Der Schritt hat kein eigenes Regelgesetz
law-not-designed-one = Das Regelgesetz ergibt nicht seine Entwurfsdynamik
# $failed of the scenario's $laws own laws.
law-not-designed-some = { $failed } von { $laws } Regelgesetzen { $failed ->
        [one] ergibt nicht seine Entwurfsdynamik
       *[other] ergeben nicht ihre Entwurfsdynamik
    }
law-never-runs = Ihr { $before } ergibt an keinem der { $draws } gezogenen Zustände einen endlichen Wert, daher wird Schritt { $step } nie ausgeführt
law-no-share = Ihr { $output } ({ $unit }) weicht dort, wo das Regelgesetz des Artikels nahezu null ist, von dem { $output } ab, das die Entwurfsdynamik ergibt; relativ zu dessen Betrag ist die Abweichung nicht endlich
# $count of the $draws drawn states; $reads is none when the law reads no signal, else $names
# lists the names it reads with their values there (law-named-value).
law-differs-infinitely = Ihr { $output } ({ $unit }) weicht an { $count } der { $draws } gezogenen Zustände unendlich weit von dem { $output } ab, das die Entwurfsdynamik ergibt{ $reads ->
        [none] , ohne ein Signal zu lesen
       *[some] , z. B. bei { $names }
    }
# As law-differs-infinitely; $value is what the law gives: inf, -inf or NaN.
law-not-finite = Ihr { $output } ({ $unit }) ist an { $count } der { $draws } gezogenen Zustände keine endliche Zahl: Es ergibt { $value }{ $reads ->
        [none] , ohne ein Signal zu lesen
       *[some] {" "}bei { $names }
    }
# A name a law reads and its value: "z1 = 0.25".
law-named-value = { $name } = { $value }
law-paper-zero = das Regelgesetz des Artikels blieb über den ganzen Lauf null, Ihres nicht
