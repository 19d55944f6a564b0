# The core's refusals of a formula, and why a law's distance from its designed dynamics is not a
# number: said as a link is read or a run ends, with the page's first messages.
# $reason es uno de los mensajes formula-*; $at cuenta los caracteres de la fórmula desde 1.
formula-at = en el carácter { $at }: { $reason }
# $written es el número tal como se escribió.
formula-not-a-number = '{ $written }' no es un número
formula-number-too-large = '{ $written }' es demasiado grande para un número
# $char es el carácter escrito.
formula-not-in-language = '{ $char }' no forma parte del lenguaje (+ − * / ^, paréntesis, nombres, números)
formula-division-by-zero = división por cero
formula-nests-too-deep = aquí la fórmula anida más de { $max } niveles
formula-ends-early = la fórmula termina donde se espera un número, un nombre o '('
formula-never-closed = este '(' no se cierra nunca
formula-expected-close = aquí se esperaba ')' o un operador
# $op es el operador escrito (* / ^ ) o ,); un producto escrito · o × se da como *.
formula-misplaced-operator = '{ $op }' donde se espera un número, un nombre o '('
# $name es el nombre escrito; $functions enumera los nombres de las funciones.
formula-no-function = no hay ninguna función '{ $name }': las funciones son { $functions }
# $name es el nombre de una función: "en sqrt( )".
formula-expected-argument-end = se esperaba ',' o ')' en { $name }( )
# $arity es cuántos argumentos toma la función; $given, cuántos recibió.
formula-arguments = { $name } toma { $arity } { $arity ->
        [one] argumento
       *[other] argumentos
    }, no { $given }
# $from es el paso cuya ley da el nombre.
formula-later-name = '{ $name }' no se conoce en el paso { $step }: viene de la ley del paso { $from }
formula-is-function = '{ $name }' es una función: escribe { $name }( )
# $name es x1, la velocidad real.
formula-true-speed = '{ $name }' es la velocidad real, que un controlador sin sensor no tiene: escribe su estimación x1h
# $name es x4 o x5, un flujo rotórico real.
formula-true-flux = '{ $name }' es un flujo rotórico real, que ningún accionamiento mide: escribe su estimación x4h o x5h
# $name es xt1, xt4 o xt5.
formula-unmeasured-error = '{ $name }' es un error de estimación de un estado no medido, que un controlador sin sensor no puede conocer: el artículo deja esos términos en d̃2 y d̃4, contra los que está diseñado el término robusto (robust·h²/(4ε)·z)
formula-unknown-name = nombre desconocido '{ $name }' (véase la lista de nombres)
formula-too-long = la fórmula tiene { $length } caracteres, más de los { $max } permitidos
formula-empty = la fórmula está vacía
formula-unopened = este ')' no tiene ningún '(' antes
formula-expected-operator = aquí se esperaba un operador (un producto se escribe con *)
formula-too-many-operations = la fórmula requiere { $operations } operaciones, más de las { $max } permitidas
formula-too-deep = la fórmula anida valores a { $depth } niveles de profundidad, más de los { $max } permitidos: escríbela con menos paréntesis anidados
# $error es un mensaje formula-*, con su posición.
law-refused = law.v{ $step }: { $error }
law-no-such-step = paso { $step }: los pasos van del 1 al 4
law-none = el escenario no tiene ninguna ley propia: indica law.v1, law.v2, law.v3 o law.v4
law-no-own-law = el paso no tiene ley propia
law-not-designed-one = la ley no da su dinámica diseñada
# $failed de las $laws leyes propias del escenario.
law-not-designed-some = { $failed ->
        [one] { $failed } de { $laws } leyes no da su dinámica diseñada
       *[other] { $failed } de { $laws } leyes no dan su dinámica diseñada
    }
law-never-runs = tu { $before } no da un valor finito en ninguno de los { $draws } estados sorteados, así que el paso { $step } nunca se ejecuta
law-no-share = tu { $output } ({ $unit }) difiere del { $output } que da la dinámica diseñada donde la ley del artículo es casi nula, y la diferencia relativa a su tamaño no es finita
# $count de los $draws estados sorteados; $reads es none cuando la ley no lee ninguna señal; si no,
# $names enumera los nombres que lee con sus valores ahí (law-named-value).
law-differs-infinitely = tu { $output } ({ $unit }) difiere infinitamente del { $output } que da la dinámica diseñada en { $count } de los { $draws } estados sorteados{ $reads ->
        [none] , sin leer ninguna señal
       *[some] , p. ej. en { $names }
    }
# Como law-differs-infinitely; $value es lo que da la ley: inf, -inf o NaN.
law-not-finite = tu { $output } ({ $unit }) no es un número finito en { $count } de los { $draws } estados sorteados: da { $value }{ $reads ->
        [none] , sin leer ninguna señal
       *[some] {" "}en { $names }
    }
# Un nombre que lee una ley y su valor: "z1 = 0.25".
law-named-value = { $name } = { $value }
law-paper-zero = la ley del artículo se quedó en cero durante toda la ejecución y la suya no
