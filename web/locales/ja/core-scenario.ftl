# シナリオについてのコアのメッセージ：リンク、設定、実行が却下された理由。CLIはこのファイルの英語版で
# 英語のまま述べ、ページは読者の言語で述べる。フィールド名、キー、値、プリセット、設定（v=1、preset=NAME、
# 'duration'、'ts'、law.v2、pwm=1）はリンク自身の文言なので、そのまま残す。引用された入力は引用符を残す。

## 却下されたシナリオ

scenario-missing = フィールド '{ $key }' がありません（シナリオは v={ $version }&preset=NAME で始まります）
scenario-unsupported-version = フィールド 'v' = '{ $value }'：対応していないコーデックのバージョンです。許容値：{ $version }
scenario-unknown-preset = フィールド 'preset' = '{ $name }'：不明なプリセットです。許容値：{ $presets }
scenario-unknown-key = '{ $key }' はシナリオのフィールドではありません（設定フォームと `imlab describe` に一覧があります）
scenario-duplicate-key = フィールド '{ $key }' が複数回指定されています
scenario-malformed = '{ $piece }' は key=value の形式ではありません
scenario-bad-value = フィールド '{ $key }' = '{ $value }'：無効な値です。期待される値：{ $expected }
scenario-out-of-range = フィールド '{ $key }' = { $value }：範囲外です。許容範囲：{ $allowed }
scenario-not-applicable = フィールド '{ $key }' は指令値 '{ $reference }' には適用されません（先に ref= を設定してください）
scenario-physics = { $which ->
        [plant] プラント（{ $which }）
       *[model] モデル（{ $which }）
    }のパラメータ：{ $error }
scenario-bad-formula = フィールド '{ $key }'：{ $error }
scenario-refused = フィールド '{ $key }'：{ $why }
scenario-law-fw = ステップ3または4の自作の制御則は一定の磁束目標値を前提に書かれていますが、fw=1 はこの目標値を動かします。fw をオフにするか、制御則を空欄にしてください
scenario-design = フィールド 'design' = 'derived'：{ $why }
design-no-voltage = 定格電圧で定常運転に使えるのは{ $available } Vですが、定格磁束と定格電流には静止時でも{ $needed } Vが必要です
scenario-too-long = シナリオの長さは{ $bytes }バイトで、許容される{ $max }バイト（{ $kib } KiB）を超えています

## フィールドがとる値

scenario-expected-formula = UTF-8でパーセントエンコードした式
scenario-expected-one-of = { $options } のいずれか
scenario-expected-number = 十進数の数値
scenario-expected-table = カンマ区切りの点 t:value（例：0:0,0.1:100）、各数値は十進数
scenario-expected-table-length = 点は{ $max }個まで。この表には{ $count }個あります
scenario-expected-table-rising = 点ごとに増加する時刻。{ $after } s は { $before } s より後ではありません
scenario-expected-table-time = 0から{ $max } sまでの時刻。{ $t } s は範囲外です
scenario-expected-table-slope = 点の間で毎秒{ $max } { $unit }までの変化。{ $before } s から { $after } s まではそれより速く変化しています
scenario-allowed-choice = { $options }
scenario-allowed-formula = ステップ{ $step }で使える名前による式（`imlab describe` に一覧があります）、または空欄
scenario-allowed-table = 点 t:value を{ $max }個まで、時刻は0から{ $duration } sまで増加、値は{ $values }。点の間は直線で結び、最初の点より前と最後の点より後は値を保持
scenario-allowed-range = { $min } { $below } { $key } ≤ { $max }
scenario-allowed-unit = { $range }（{ $unit }）
scenario-allowed-whole = { $range }、整数
scenario-allowed-pwm = pwm=1 は vlimit=circle または hex とのみ併用可（二レベルインバータでは正方形の制限の角の電圧を出せないため）

## 大きすぎる実行

scenario-too-many-samples = 'duration'/'ts' = { $duration } s / { $ts } s = { $samples }サンプルは、許容される{ $max }を超えています。'duration' を短くするか、'ts' を大きくしてください
scenario-shorter-than-sample = 'duration' = { $duration } s は一サンプルの長さ 'ts' = { $ts } s より短くなっています
scenario-too-much-work =
    実行の計算量、{ $samples }サンプル（'duration'/'ts' = { $duration } s / { $ts } s）× サンプルあたり{ $per_sample }回のプラントのRK4ステップ（{ $how }）= { $work }ステップは、許容される{ $max }を超えています。'substeps' か 'duration' を小さくするか、'ts' を大きくしてください{ $pwm ->
        [yes] （または 'pwm' をオフにしてください）
       *[no] {""}
    }
scenario-work-substeps = 'substeps' = { $substeps }
scenario-work-substeps-pwm = 7個のPWM区間それぞれで 'substeps' = { $substeps }
scenario-work-prediction = { $plant }、および理想オブザーバの予測（'delay.comp'）に{ $substeps }
scenario-law-work = 制御則の計算量、{ $samples }サンプル（'duration'/'ts' = { $duration } s / { $ts } s）× サンプルあたり{ $per_sample }演算（{ $parts }）= { $work } は、許容される{ $max }を超えています（正弦と余弦は64演算、べき乗は32演算、exp、ln、tanh、atan2はそれぞれ12演算と数えます）。サンプルあたり高々{ $fits }演算の制御則を書くか、'duration' を { $duration_fit } s に短くするか、'ts' を { $ts_fit } s に大きくしてください
scenario-law-work-step = law.v{ $step } { $work }
scenario-law-work-rates = 自作のv1とv3の変化率 { $work }
scenario-trace-too-large =
    { $rows }サンプル × { $columns }列の記録には{ $mib } MiBが必要で、許容される{ $max } MiBを超えています。'duration' を短くするか、'ts' を大きくしてください{ $fewer ->
        [yes] （または、より大きな 'every' で記録するサンプルを減らしてください）
       *[no] {""}
    }
sweep-run-too-large = スイープの各実行は{ $samples }サンプル（{ $mib } MiB）を保持し、許容される{ $max } MiBを超えています。スイープの実行時間を短くするか、'ts' を大きくしてください

## 物理的でない電動機パラメータ

param-not-positive = { $name } = { $value }：> 0 の有限の数でなければなりません
param-negative = { $name } = { $value }：≥ 0 の有限の数でなければなりません
param-sigma = 漏れインダクタンス σ = Ls − M²/Lr = { $sigma } H は > 0 でなければなりません（M = { $m }、Ls = { $ls }、Lr = { $lr }）：M² は Ls·Lr より小さくなければなりません
scenario-allowed-every = 1 ≤ every

## 却下されたスイープの実行

sweep-allowed-amp = スイープでは 0 < sine.amp
sweep-allowed-nyquist = ナイキスト周波数 1/(2·Ts) = { $nyquist } Hz 未満
sweep-allowed-period = 当てはめ区間に少なくとも一周期：{ $duration } s の実行では freq ≥ { $least } Hz
sweep-allowed-measurable = スイープで測定できる振幅：{ $reason }。振幅を大きくしてください
sweep-unresolved = 当てはめ区間でω_d自身を当てはめると{ $found } rad/sとなり、{ $tolerance } %を超えてずれています（振幅の二乗がアンダーフローするか、オフセット + 振幅が丸められてオフセット { $offset } rad/s になります）
sweep-too-small = { $freq } Hzでは応答が { $name } = { $value } と読まれ、当てはめには小さすぎます

## 一覧

core-list-separator = {"、"}
field-idle = { $because } では { $key } は効果がありません
